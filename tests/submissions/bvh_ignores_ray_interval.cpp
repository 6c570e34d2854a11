// Grader self-test submission (stage 05_bvh): the traversal searches [0, infinity), not the
// incoming ray's [t_min, t_max]. Every camera ray starts with [0, infinity), so the picture and the
// work test pass; the rays that end before their first hit or start past it do not.
#define BVH_SUBMISSION(mistakes, report) mistakes.ignores_ray_interval = true
#include "bvh_submission.h"
