// The HTML report of a grading run, <output>/index.html (grading-output/ by default): the score
// table; per stage the tests that lost points with their failures (inputs, expected, got) and
// hints; for every image test the student's picture, the reference and their difference side by
// side, with a slider between the first two; links to the handouts. One static file with its
// style and script inside, the pictures as files beside it: no server, nothing from the network.
// Every text comes from the catalogue (messages.def) in this run's language.
//
// The judge writes it alone, after every stage process is gone, like results.json: nothing the
// stage code printed is more than escaped text on the page.
#pragma once

#include "results.h"

#include <string>
#include <vector>

namespace raylab::grading {

// Writes <directory>/index.html in this run's language (replacing whatever was there, as
// results.json is replaced) and returns its path. Throws std::runtime_error if it cannot.
std::string write_report_html(const std::vector<StageResult>& results, const Message& description,
                              const std::string& directory);

// The page itself. `kit_href` is the URL of the kit's folder (the one holding docs/) relative to
// the page's folder, e.g. "..".
std::string report_html(const std::vector<StageResult>& results, const Message& description, Language language,
                        const std::string& kit_href);

// `text` as HTML text: & < > " ' as entities, control characters but tab and newline as '?',
// bytes that are not UTF-8 as U+FFFD.
std::string escape_html(const std::string& text);

}  // namespace raylab::grading
