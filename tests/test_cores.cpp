// How many threads a render starts by default (cores.h): the cores of the process's affinity,
// no more than its cgroup's CPU quota (v1 or v2, set on its own folder or one above), rounded up.
// The cgroup files are faked in a folder of their own. And how many threads the address-space
// limit has room for.
#include "raylab/cores.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <thread>

namespace raylab {
namespace {

namespace fs = std::filesystem;

class Cores : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("raylab-cores-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }
  void write(const std::string& relative, const std::string& text) {
    fs::create_directories((root_ / relative).parent_path());
    std::ofstream(root_ / relative) << text;
  }
  unsigned cores(unsigned affinity, const std::string& proc_self_cgroup) {
    return usable_cores(affinity, proc_self_cgroup, root_.string());
  }
  fs::path root_;
};

TEST_F(Cores, WithoutAQuotaEveryCoreOfTheAffinity) {
  EXPECT_EQ(cores(6, "0::/user.slice\n"), 6u);
  write("user.slice/cpu.max", "max 100000\n");
  EXPECT_EQ(cores(6, "0::/user.slice\n"), 6u);
  EXPECT_EQ(cores(6, ""), 6u) << "no cgroup at all";
}

TEST_F(Cores, HalfACpuIsOneThread) {  // Gradescope's default: docker --cpus 0.5
  write("docker/abc/cpu.max", "50000 100000\n");
  EXPECT_EQ(cores(64, "0::/docker/abc\n"), 1u);
}

TEST_F(Cores, AQuotaIsRoundedUp) {
  write("docker/abc/cpu.max", "150000 100000\n");
  EXPECT_EQ(cores(64, "0::/docker/abc\n"), 2u);
  write("docker/abc/cpu.max", "200000 100000\n");
  EXPECT_EQ(cores(64, "0::/docker/abc\n"), 2u) << "exactly 2 CPUs";
}

TEST_F(Cores, AQuotaAboveTheProcessHoldsToo) {
  write("machine/cpu.max", "300000 100000\n");
  write("machine/job/cpu.max", "max 100000\n");
  EXPECT_EQ(cores(64, "0::/machine/job\n"), 3u);
}

TEST_F(Cores, AContainersOwnQuotaAtTheRootOfItsView) {
  // In a container, /proc/self/cgroup may name a path the container does not see; the limit is
  // then in the folder the container's cgroup file system shows as its root.
  write("cpu.max", "100000 100000\n");
  EXPECT_EQ(cores(64, "0::/../../system.slice/docker-abc.scope\n"), 1u);
}

TEST_F(Cores, CgroupVersionOneUnderEitherMountName) {
  write("cpu,cpuacct/docker/abc/cpu.cfs_quota_us", "150000\n");
  write("cpu,cpuacct/docker/abc/cpu.cfs_period_us", "100000\n");
  EXPECT_EQ(cores(64, "11:memory:/docker/abc\n4:cpu,cpuacct:/docker/abc\n"), 2u);
  fs::remove_all(root_ / "cpu,cpuacct");
  write("cpu/docker/abc/cpu.cfs_quota_us", "-1\n");  // no quota
  write("cpu/docker/abc/cpu.cfs_period_us", "100000\n");
  EXPECT_EQ(cores(64, "4:cpu,cpuacct:/docker/abc\n"), 64u);
  write("cpu/docker/abc/cpu.cfs_quota_us", "50000\n");
  EXPECT_EQ(cores(64, "4:cpu,cpuacct:/docker/abc\n"), 1u);
}

TEST_F(Cores, TheAffinityBoundsAGenerousQuota) {  // taskset -c 0,1 inside 8 CPUs' quota
  write("job/cpu.max", "800000 100000\n");
  EXPECT_EQ(cores(2, "0::/job\n"), 2u);
}

TEST_F(Cores, UnreadableFilesAreNoQuota) {
  write("job/cpu.max", "half a cpu\n");
  write("cpu/job/cpu.cfs_quota_us", "\n");
  EXPECT_EQ(cores(4, "0::/job\n4:cpu:/job\nnot a line\n"), 4u);
  write("job/cpu.max", "0 100000\n");
  EXPECT_EQ(cores(4, "0::/job\n"), 4u) << "a zero quota is no quota (the kernel refuses one)";
}

TEST(ThreadsWithinAddressSpaceLimit, EachNeedsItsStackAndAnArena) {
  constexpr std::uint64_t MiB = std::uint64_t{1} << 20;
  EXPECT_EQ(threads_within_address_space_limit(0, 100 * MiB, 8 * MiB), std::numeric_limits<unsigned>::max())
      << "no limit";
  EXPECT_EQ(threads_within_address_space_limit(400 * MiB, 100 * MiB, 8 * MiB), 4u) << "300 MiB free / 72 MiB";
  EXPECT_EQ(threads_within_address_space_limit(400 * MiB, 350 * MiB, 8 * MiB), 0u);
  EXPECT_EQ(threads_within_address_space_limit(400 * MiB, 500 * MiB, 8 * MiB), 0u) << "over the limit already";
}

TEST(ThreadsWithinAddressSpaceLimit, ThisProcessWithoutALimitHasNoBound) {
  rlimit limit{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &limit), 0);
  if (limit.rlim_cur != RLIM_INFINITY) GTEST_SKIP() << "this test runs under an address-space limit";
  EXPECT_EQ(threads_within_address_space_limit(), std::numeric_limits<unsigned>::max());
}

TEST(UsableCores, ThisProcessHasAtLeastOneAndNoMoreThanTheMachine) {
  const unsigned cores = usable_cores();
  EXPECT_GE(cores, 1u);
  EXPECT_LE(cores, std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace
}  // namespace raylab
