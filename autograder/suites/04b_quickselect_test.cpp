// Autograder suite for stage 04b_quickselect (20 points).
//
// The keys stay in the judge: the stage code gets the items (numbers drawn per run, never
// positions) and asks the judge for every comparison (04b_quickselect_calls.cpp), so the judge
// counts them all and the stage cannot know the answer without the work. Every call's result is
// checked, the work tests' too: a call that does nothing earns nothing.
//
// The work tests and their false-failure rate: on random keys the test fails a selection whose
// comparisons per item at n = 8,192 are more than 12 AND more than 1.25 times those at n = 512
// (4 calls at 512, 2 at 2,048, 1 at 8,192: each comparison is a round trip to the judge, about
// 25 microseconds, so the test asks for some 70,000 of them, under 2 s).
// A sort's grow like log n (Hoare's quicksort, tests/submissions/quickselect_sorts_both_sides:
// 10.8 at 512, 15.8 at 8,192, 1.46 times); a correct selection's stay level, about 3 to 5 with a
// random pivot (the reference 4.9-5.0) and 8.6 to 9.7 for the median of medians
// (quickselect_median_of_medians), so it passes whatever its random pivots did. Any call on
// random keys stops at kMostPerItem per item. On sorted, reversed and all-equal keys a call stops
// at kMostPerItem per item: a quadratic one needs n / 4 or more (512 at n = 2,048).
// Not told apart here (the handout's contract asks for them all the same): a selection by a heap
// of the k + 1 smallest, O(n log n) with a small constant (about 4 per item at 512 and 6 at
// 16,384, under both bounds, and less at 8,192; the random pivots' noise hides its growth at these
// sizes), and a fixed middle pivot, quadratic only on inputs built against it.
#include "grading.h"
#include "support.h"

#include "raylab/stages/04b_quickselect.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "04b_quickselect";
const bool kRegistered = register_stage(kStage, [] {
  std::uint32_t items[2] = {7, 3};
  select_kth(items, 2, 0, ItemOrder{[](const void*, std::uint32_t a, std::uint32_t b) { return a < b; }, nullptr});
});

// The most comparisons per item a call may make before it is stopped (plus kSlack): far above
// what any linear selection needs, far below what a quadratic one needs on 2,048 items.
constexpr std::uint64_t kMostPerItem = 40, kSlack = 256;

// One call's input: the keys in the array's order, and the position wanted.
struct Case {
  std::vector<std::uint32_t> keys;
  std::size_t k = 0;
  MessageId input = MessageId::select_input_random;
};

// The keys of one call's items, in the judge, and the comparisons it answered.
struct JudgeOrder {
  std::unordered_map<std::uint32_t, std::uint32_t> key_of;
  std::uint64_t comparisons = 0, most = 0;
};

// Thrown out of the judge's order, through the call (the server is stopped): the stage made too
// many comparisons, or compared a number that is not one of its items.
struct ComparisonLimitReached {};
struct ForeignItem {
  std::uint32_t item;
};

bool judge_less(const void* context, std::uint32_t a, std::uint32_t b) {
  auto* order = static_cast<JudgeOrder*>(const_cast<void*>(context));
  const auto key_a = order->key_of.find(a), key_b = order->key_of.find(b);
  if (key_a == order->key_of.end()) throw ForeignItem{a};
  if (key_b == order->key_of.end()) throw ForeignItem{b};
  if (++order->comparisons > order->most) throw ComparisonLimitReached{};
  return key_a->second < key_b->second;
}

std::mt19937_64& random_numbers() {
  // Drawn per run (a seed the stage server cannot know), so no answer can be learnt in advance.
  static std::mt19937_64 numbers(test_seed(std::random_device{}()));
  return numbers;
}

// The item numbers the stage sees, from a generator of their own: hundreds of them in a row must
// tell nothing of the keys' generator.
std::mt19937_64& item_numbers() {
  static std::mt19937_64 numbers(std::random_device{}());
  return numbers;
}

std::string call_text(const Case& c) {
  return "select_kth(" + std::to_string(c.keys.size()) + " items, k = " + std::to_string(c.k) + ")";
}

std::string keys_text(const std::vector<std::uint32_t>& keys) {
  std::string text = "{";
  for (std::size_t i = 0; i < keys.size() && i < 16; ++i) text += (i ? ", " : "") + std::to_string(keys[i]);
  if (keys.size() > 16) text += ", ... " + std::to_string(keys.size() - 16);
  return text + "}";
}

// How a call ended, as the judge saw it.
struct Outcome {
  bool right = false;           // the same items, arranged as the contract says
  bool limit_reached = false;   // stopped after `most` comparisons
  std::uint64_t comparisons = 0;
};

// Runs one call and checks its result; a wrong one gets its failure (and, with `hints`, the hint
// that names what went wrong).
Outcome run(const Case& c, std::uint64_t most_comparisons, bool hints = true) {
  JudgeOrder order;
  order.most = most_comparisons;
  std::vector<std::uint32_t> items(c.keys.size());
  {
    // Distinct numbers, not positions: the stage sees only them.
    std::unordered_set<std::uint32_t> used;
    for (std::uint32_t& item : items) {
      do item = static_cast<std::uint32_t>(item_numbers()());
      while (!used.insert(item).second);
    }
  }
  for (std::size_t i = 0; i < items.size(); ++i) order.key_of[items[i]] = c.keys[i];
  const std::vector<std::uint32_t> before = items;

  Outcome outcome;
  try {
    select_kth(items.data(), items.size(), c.k, ItemOrder{&judge_less, &order});
  } catch (const ComparisonLimitReached&) {
    outcome.limit_reached = true;
    outcome.comparisons = order.comparisons - 1;
    add_failure({MessageId::select_failure_comparison_limit,
                 {{"call", call_text(c)}, {"input", Message(c.input)}, {"limit", std::to_string(most_comparisons)},
                  {"per_item", std::to_string(most_comparisons / std::max<std::size_t>(1, c.keys.size()))}}});
    return outcome;
  } catch (const ForeignItem& foreign) {
    add_failure({MessageId::select_failure_foreign_item, {{"call", call_text(c)}, {"item", std::to_string(foreign.item)}}});
    if (hints) add_hint(MessageId::select_hint_foreign_item);
    return outcome;
  }
  outcome.comparisons = order.comparisons;
  if (c.k >= c.keys.size()) return outcome;  // it should have thrown: the caller says so

  // The same items, each once.
  std::vector<std::uint32_t> sorted_before = before, sorted_after = items;
  std::sort(sorted_before.begin(), sorted_before.end());
  std::sort(sorted_after.begin(), sorted_after.end());
  if (sorted_before != sorted_after) {
    std::vector<std::uint32_t> lost, extra;
    std::set_difference(sorted_before.begin(), sorted_before.end(), sorted_after.begin(), sorted_after.end(),
                        std::back_inserter(lost));
    std::set_difference(sorted_after.begin(), sorted_after.end(), sorted_before.begin(), sorted_before.end(),
                        std::back_inserter(extra));
    add_failure({MessageId::select_failure_not_same_items,
                 {{"call", call_text(c)}, {"keys", keys_text(c.keys)}, {"lost", std::to_string(lost.size())},
                  {"extra", std::to_string(extra.size())}}});
    std::vector<std::uint32_t> distinct = c.keys;
    std::sort(distinct.begin(), distinct.end());
    const bool equal_keys = std::adjacent_find(distinct.begin(), distinct.end()) != distinct.end();
    if (hints) add_hint(equal_keys ? MessageId::select_hint_loses_equal_keys : MessageId::select_hint_loses_items);
    return outcome;
  }

  // items[k] has the kth key; none before it is greater, none after it smaller.
  std::vector<std::uint32_t> sorted_keys = c.keys;
  std::sort(sorted_keys.begin(), sorted_keys.end());
  const std::uint32_t expected = sorted_keys[c.k], got = order.key_of[items[c.k]];
  if (got != expected) {
    add_failure({MessageId::select_failure_wrong_kth,
                 {{"call", call_text(c)}, {"keys", keys_text(c.keys)}, {"k", std::to_string(c.k)},
                  {"got", std::to_string(got)}, {"expected", std::to_string(expected)}}});
    for (const std::size_t position : {c.k - 1, c.k + 1})
      if (position < sorted_keys.size() && sorted_keys[position] == got && hints)
        add_hint({MessageId::select_hint_k_off_by_one, {{"position", std::to_string(position)}, {"k", std::to_string(c.k)}}});
    return outcome;
  }
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::uint32_t key = order.key_of[items[i]];
    if ((i < c.k && key > expected) || (i > c.k && key < expected)) {
      add_failure({MessageId::select_failure_wrong_side,
                   {{"call", call_text(c)}, {"keys", keys_text(c.keys)}, {"k", std::to_string(c.k)},
                    {"expected", std::to_string(expected)}, {"i", std::to_string(i)}, {"key", std::to_string(key)}}});
      if (hints) add_hint(MessageId::select_hint_sides);
      return outcome;
    }
  }
  outcome.right = true;
  return outcome;
}

// The limit of a correctness call: quadratic work passes there (the work tests judge it), an
// endless loop of comparisons does not.
std::uint64_t correctness_limit(std::size_t count) { return 4 * count * count + kSlack; }
std::uint64_t work_limit(std::size_t count) { return kMostPerItem * count + kSlack; }

// Runs the cases until the first wrong result (its failure says which).
void expect_right(const std::vector<Case>& cases) {
  for (const Case& c : cases)
    if (!run(c, correctness_limit(c.keys.size())).right) return;
}

std::vector<std::uint32_t> random_keys(std::size_t count, std::uint32_t distinct_values) {
  std::uniform_int_distribution<std::uint32_t> key(0, distinct_values - 1);
  std::vector<std::uint32_t> keys(count);
  for (std::uint32_t& value : keys) value = key(random_numbers());
  return keys;
}

// 0 .. count - 1 in a random order: distinct keys.
std::vector<std::uint32_t> shuffled_keys(std::size_t count) {
  std::vector<std::uint32_t> keys(count);
  std::iota(keys.begin(), keys.end(), 0u);
  std::shuffle(keys.begin(), keys.end(), random_numbers());
  return keys;
}

std::vector<std::uint32_t> sorted_keys(std::size_t count) {
  std::vector<std::uint32_t> keys(count);
  std::iota(keys.begin(), keys.end(), 10u);
  return keys;
}

std::vector<std::uint32_t> reversed_keys(std::size_t count) {
  std::vector<std::uint32_t> keys = sorted_keys(count);
  std::reverse(keys.begin(), keys.end());
  return keys;
}

std::size_t random_position(std::size_t count) {
  return std::uniform_int_distribution<std::size_t>(0, count - 1)(random_numbers());
}

GRADED_TEST(kStage, Stage04bQuickselect, SelectsTheKthOfDistinctKeys, 3) {
  std::vector<Case> cases;
  for (std::size_t count = 1; count <= 12; ++count)
    for (std::size_t k = 0; k < count; ++k) cases.push_back({shuffled_keys(count), k});
  for (const std::size_t count : {33, 100, 400})
    for (int i = 0; i < 3; ++i) cases.push_back({shuffled_keys(count), random_position(count)});
  expect_right(cases);
}

GRADED_TEST(kStage, Stage04bQuickselect, SortedAndReversedKeys, 2) {
  std::vector<Case> cases;
  for (std::size_t count = 2; count <= 9; ++count)
    for (std::size_t k = 0; k < count; ++k) {
      cases.push_back({sorted_keys(count), k, MessageId::select_input_sorted});
      cases.push_back({reversed_keys(count), k, MessageId::select_input_reversed});
    }
  for (const std::size_t count : {101, 200})
    for (const std::size_t k : {std::size_t{0}, count / 2, count - 1}) {
      cases.push_back({sorted_keys(count), k, MessageId::select_input_sorted});
      cases.push_back({reversed_keys(count), k, MessageId::select_input_reversed});
    }
  expect_right(cases);
}

GRADED_TEST(kStage, Stage04bQuickselect, KeepsEqualKeys, 3) {
  std::vector<Case> cases;
  for (const std::size_t count : {1, 2, 5, 50, 200})
    cases.push_back({std::vector<std::uint32_t>(count, 7u), count / 2, MessageId::select_input_all_equal});
  for (std::size_t count = 2; count <= 12; ++count)
    for (std::size_t k = 0; k < count; ++k) cases.push_back({random_keys(count, 3), k});
  for (const std::size_t count : {64, 300})
    for (const std::uint32_t values : {2u, 5u, 30u})
      for (int i = 0; i < 2; ++i) cases.push_back({random_keys(count, values), random_position(count)});
  expect_right(cases);
}

GRADED_TEST(kStage, Stage04bQuickselect, KAtBothEnds, 2) {
  std::vector<Case> cases;
  for (std::size_t count = 1; count <= 64; count += count < 8 ? 1 : 7) {
    cases.push_back({shuffled_keys(count), 0});
    cases.push_back({shuffled_keys(count), count - 1});
  }
  cases.push_back({random_keys(40, 4), 0});
  cases.push_back({random_keys(40, 4), 39});
  expect_right(cases);
}

GRADED_TEST(kStage, Stage04bQuickselect, RejectsKBeyondTheEnd, 1) {
  // A right call first: a function that only throws earns nothing.
  if (!run({shuffled_keys(16), 5}, correctness_limit(16)).right) return;
  for (const Case& c : {Case{shuffled_keys(8), 8}, Case{{}, 0}, Case{shuffled_keys(3), 100}}) {
    bool threw = false;
    try {
      run(c, correctness_limit(c.keys.size()), /*hints=*/false);
    } catch (const std::invalid_argument&) {
      threw = true;
    }
    if (!threw) {
      add_failure({MessageId::select_failure_no_throw, {{"call", call_text(c)}}});
      return;
    }
  }
}

// The mean comparisons per item of `calls` calls on `count` random distinct keys, k anywhere in
// the middle half; nullopt after a wrong result or a call stopped at its limit (a failure).
std::optional<double> per_item_on_random_keys(std::size_t count, int calls) {
  std::uint64_t comparisons = 0;
  for (int i = 0; i < calls; ++i) {
    const std::size_t k = count / 4 + random_position(count / 2);
    const Outcome outcome = run({shuffled_keys(count), k}, work_limit(count));
    if (!outcome.right) return std::nullopt;
    comparisons += outcome.comparisons;
  }
  return double(comparisons) / (double(count) * calls);
}

std::string per_item_text(double per_item) {
  std::ostringstream text;
  text.precision(2);
  text << std::fixed << per_item;
  return text.str();
}

GRADED_TEST(kStage, Stage04bQuickselect, ComparisonsGrowLinearly, 4) {
  const std::vector<std::pair<std::size_t, int>> sizes = {{512, 4}, {2048, 2}, {8192, 1}};
  std::vector<double> per_item;
  std::string table;
  for (const auto& [count, calls] : sizes) {
    const std::optional<double> measured = per_item_on_random_keys(count, calls);
    if (!measured) return;
    per_item.push_back(*measured);
    table += (table.empty() ? "" : "; ") + std::string("n = ") + std::to_string(count) + ": " + per_item_text(*measured);
  }
  add_note({MessageId::select_note_comparisons, {{"input", Message(MessageId::select_input_random)}, {"table", table}}});
  if (per_item.back() > 12 && per_item.back() > 1.25 * per_item.front()) {
    add_failure({MessageId::select_failure_grows,
                 {{"small", per_item_text(per_item.front())}, {"large", per_item_text(per_item.back())}}});
    add_hint(MessageId::select_hint_recurses_both_sides);
  }
}

// Each input at n = 2,048 with k in the middle: fails at the first call stopped at its limit or
// wrong, with `hint`.
void expect_no_blow_up(const std::vector<Case>& cases, MessageId hint) {
  std::string table;
  for (const Case& c : cases) {
    const Outcome outcome = run(c, work_limit(c.keys.size()));
    if (outcome.limit_reached) add_hint(hint);
    if (!outcome.right) return;
    add_note({MessageId::select_note_comparisons,
              {{"input", Message(c.input)},
               {"table", "n = " + std::to_string(c.keys.size()) + ": " +
                             per_item_text(double(outcome.comparisons) / double(c.keys.size()))}}});
  }
}

GRADED_TEST(kStage, Stage04bQuickselect, NoBlowUpOnSortedKeys, 3) {
  constexpr std::size_t kCount = 2048;
  expect_no_blow_up({{reversed_keys(kCount), kCount / 2, MessageId::select_input_reversed},
                     {sorted_keys(kCount), kCount / 2 + 1, MessageId::select_input_sorted}},
                    MessageId::select_hint_fixed_pivot);
}

GRADED_TEST(kStage, Stage04bQuickselect, NoBlowUpOnEqualKeys, 2) {
  constexpr std::size_t kCount = 2048;
  expect_no_blow_up({{random_keys(kCount, 2), kCount / 2, MessageId::select_input_two_keys},
                     {std::vector<std::uint32_t>(kCount, 7u), kCount / 2, MessageId::select_input_all_equal}},
                    MessageId::select_hint_equal_keys_one_side);
}

}  // namespace
}  // namespace raylab::grading
