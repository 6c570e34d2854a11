// The judge's side of the pipes to a stage server (stage_process.h, protocol.h) against a server
// that misbehaves on purpose (stage_process_test_server.cpp): every read and write ends by the
// call's deadline, whatever the server does, and a reply over its limit is refused from its
// header; and memory a server holds outside its address space stops it where the judge gives
// stages a cgroup. The ctest judge_pipes_hold_their_deadlines. (Whether each ends soon after its deadline
// is not asserted: no test here depends on the machine's speed; a hang would stop the ctest at
// its time-out.)
#include "protocol.h"
#include "stage_process.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace raylab::grading {
namespace {

class StageProcessAgainst : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { prepare_judge(); }

  void start(const char* mode, long memory_limit_mb = 256) {
#ifdef _WIN32
    _putenv_s("RAYLAB_TEST_SERVER", mode);
#else
    ::setenv("RAYLAB_TEST_SERVER", mode, 1);
#endif
    SandboxLimits limits;
    limits.memory_limit_mb = memory_limit_mb;
    process.start(RAYLAB_TEST_SERVER_PATH, limits);
  }
  static Clock::time_point soon() { return Clock::now() + std::chrono::milliseconds(300); }
  void TearDown() override {
    std::string output;
    if (process.running()) process.stop(true, output);
  }

  StageProcess process;
};

TEST_F(StageProcessAgainst, AnHonestServer) {
  start("echo");
  const std::string request(200000, 'r');  // more than a pipe holds: written in pieces
  ASSERT_TRUE(process.send(request, Clock::now() + std::chrono::seconds(60)));
  std::string reply;
  ASSERT_EQ(process.receive(reply, 1u << 20, Clock::now() + std::chrono::seconds(60)), protocol::FrameRead::kFrame);
  EXPECT_EQ(reply, request);
}

TEST_F(StageProcessAgainst, AServerThatStopsInTheMiddleOfAFrame) {
  start("partial");
  ASSERT_TRUE(process.send("call", soon()));
  std::string reply;
  EXPECT_EQ(process.receive(reply, 1u << 20, soon()), protocol::FrameRead::kTimedOut);
}

TEST_F(StageProcessAgainst, AServerThatNeverReads) {
  start("unread");
  const std::string request(4u << 20, 'r');  // far more than the pipe holds
  EXPECT_FALSE(process.send(request, soon()));
}

TEST_F(StageProcessAgainst, AServerThatAnnouncesAHugeFrame) {
  start("huge");
  ASSERT_TRUE(process.send("call", soon()));
  std::string reply;
  try {
    process.receive(reply, 1u << 20, Clock::now() + std::chrono::seconds(60));
    ADD_FAILURE() << "a frame of 256 MiB was accepted under a limit of 1 MiB";
  } catch (const protocol::ProtocolError& e) {
    EXPECT_EQ(e.problem.id, MessageId::protocol_frame_too_large);
  }
  EXPECT_LT(reply.capacity(), std::size_t{1} << 20);  // nothing allocated for it
}

TEST_F(StageProcessAgainst, AServerThatFloodsQuestionsAndReadsNoAnswer) {
  start("flood");
  const auto deadline = Clock::now() + std::chrono::seconds(2);
  ASSERT_TRUE(process.send("call", deadline));
  // The judge answers each question; the answers fill the pipe the server does not read, and then
  // a send ends at the deadline instead of blocking (each answer is as long as a large one).
  const std::string answer(4096, 'a');
  bool ended = false;
  for (int question = 0; question < 1000000 && !ended; ++question) {
    std::string reply;
    const protocol::FrameRead read = process.receive(reply, 1u << 20, deadline);
    if (read != protocol::FrameRead::kFrame) {
      ended = true;
      break;
    }
    ended = !process.send(answer, deadline);
  }
  EXPECT_TRUE(ended);
}

#ifdef __linux__
// 55 MiB in memfds, memory that an address-space limit does not count, under a limit of 48 MiB:
// where the judge gives each stage a cgroup of its own (as root, where the kernel lets it:
// stage_cgroup_version), the kernel stops the server at the limit and the stage loses
// the call with the limit's name; elsewhere the server keeps that memory until its stage ends.
TEST_F(StageProcessAgainst, AServerThatHoldsMemoryOutsideItsAddressSpace) {
  start("hoard", 48);
  ASSERT_TRUE(process.send("call", Clock::now() + std::chrono::seconds(60)));
  std::string reply, output;
  const protocol::FrameRead read = process.receive(reply, 1u << 20, Clock::now() + std::chrono::seconds(60));
  const ProcessEnd end = process.stop(true, output);
  if (stage_cgroup_version() > 0) {
    EXPECT_EQ(read, protocol::FrameRead::kEnd) << "the server answered: it held 55 MiB under a cgroup of 48 MiB";
    EXPECT_TRUE(end.crashed);
    EXPECT_EQ(end.crash.id, MessageId::crash_memory_limit) << render(end.crash, Language::English);
  } else {
    EXPECT_EQ(read, protocol::FrameRead::kFrame) << "without a cgroup, nothing stops memory held outside the address space";
  }
}
#endif

}  // namespace
}  // namespace raylab::grading
