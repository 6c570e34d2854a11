// Stage 04b's calls between the judge and the stage server (autograder/runner/stage_call.h).
// select_kth crosses with its items and k; the order it is given stays in the judge: each
// comparison the stage code makes is a question to the judge (ask_judge), answered there by the
// caller's order. The judge thus sees, and its order counts, every comparison; the keys never
// reach the stage server, whose order is the same function for every call.
#include "stage_call.h"

#include "raylab/stages/04b_quickselect.h"

#include <algorithm>
#include <vector>

namespace raylab {
namespace {
constexpr grading::StageCall kSelectKth{"select_kth", "select_kth"};
}  // namespace

#if RAYLAB_JUDGE
void select_kth(std::uint32_t* items, std::size_t count, std::size_t k, const ItemOrder& order) {
  grading::protocol::Writer arguments;
  arguments.put_vector(std::vector<std::uint32_t>(items, items + count));
  arguments.put<std::uint64_t>(k);
  const std::vector<std::uint32_t> arranged = grading::remote(
      kSelectKth, arguments,
      [count](grading::protocol::Reader& in) {
        std::vector<std::uint32_t> read = in.get_vector<std::uint32_t>();
        in.expect_end();
        if (read.size() != count)
          throw grading::protocol::ProtocolError(grading::MessageId::protocol_wrong_item_count);
        return read;
      },
      [order](grading::protocol::Reader& question, grading::protocol::Writer& answer) {
        const auto a = question.get<std::uint32_t>();
        const auto b = question.get<std::uint32_t>();
        question.expect_end();
        answer.put<std::uint8_t>(order.less(order.context, a, b) ? 1 : 0);
      });
  std::copy(arranged.begin(), arranged.end(), items);
}
#else
namespace {

bool less_through_judge(const void*, std::uint32_t a, std::uint32_t b) {
  grading::protocol::Writer question;
  question.put(a);
  question.put(b);
  const std::string answer = grading::ask_judge(question);
  grading::protocol::Reader in(answer);
  return in.get<std::uint8_t>() != 0;
}

void serve_select_kth(grading::protocol::Reader& in, grading::protocol::Writer& out) {
  std::vector<std::uint32_t> items = in.get_vector<std::uint32_t>();
  const auto k = in.get<std::uint64_t>();
  select_kth(items.data(), items.size(), static_cast<std::size_t>(k), ItemOrder{&less_through_judge, nullptr});
  out.put_vector(items);
}

const bool kServed = grading::serve(kSelectKth, serve_select_kth);

}  // namespace
#endif

}  // namespace raylab
