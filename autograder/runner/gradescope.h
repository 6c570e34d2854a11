// What results.json carries for Gradescope beyond the scores (results_json.cpp writes it): each
// test's output as Markdown with its pictures inlined, who may see each test, and a leaderboard.
// The fields follow Gradescope's autograder specification (docs/instructors.md, "Grade on
// Gradescope"): a test's "output_format" "md" and "visibility"; the run's "execution_time" and
// "leaderboard" (entries {name, value, order}).
#pragma once

#include "results.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace raylab::grading {

// One --visibility rule: the tests it names ("" every test; a stage's id or short id, all its
// tests; "05_bvh: Bunny*", a test name with * wildcards) and what Gradescope shows them as.
struct VisibilityRule {
  std::string pattern;
  std::string level;  // visible, hidden, after_due_date or after_published
};

// "LEVEL" or "PATTERN=LEVEL"; nullopt with `error` set when the level is not one of Gradescope's.
std::optional<VisibilityRule> parse_visibility_rule(const std::string& text, std::string& error);

struct GradescopeOptions {
  std::vector<VisibilityRule> visibility;  // the last rule naming a test decides; none: visible
  double run_seconds = 0;                   // the whole grading run
};

// The visibility of the test "<stage id>: <test name>".
std::string test_visibility(const StageResult& stage, const TestResult& test, const std::vector<VisibilityRule>& rules);

// A test's output in Markdown, in `language`: its failures, hints and notes one per list item;
// for a test that lost points, the pictures its messages name (yours | reference | difference)
// inlined as PNG data, if they are in the output folder (output_directory()).
std::string test_markdown(const TestResult& test, Language language);

// Work and speed where the tests measured them: nodes and triangles per ray of your BVH
// traversal, your SAH tree's cost, and the seconds of each image test that passed (the picture
// is rendered with your code).
nlohmann::json leaderboard(const std::vector<StageResult>& results);

}  // namespace raylab::grading
