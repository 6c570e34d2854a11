// Grader self-test submission (stage 05_bvh): the reference with the near and far child
// swapped: the far child is entered first, the near one pushed. Correct answers, more work;
// expected hint: "visits the far child first".
#define BVH_SUBMISSION(mistakes, report) mistakes.far_child_first = true
#include "bvh_submission.h"
