// Hostile: the reference triangle test, plus a static initialiser that calls exit(0) when the
// program starts: no stage function ever answers, so every stage scores 0, each with the
// reason "exited (status 0)", and the grader itself finishes normally. (A triangle file: every
// stage server links it, as none grades with the grader's own triangle test.)
#include "../../solutions/03_triangle/triangle.cpp"

#include <cstdlib>

namespace {

struct ExitAtOnce {
  ExitAtOnce() { std::exit(0); }
} exit_at_once;

}  // namespace
