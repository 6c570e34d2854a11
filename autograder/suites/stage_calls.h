// Kept only for 07_sampling_test.cpp, which includes it: a suite includes its own stage's calls
// header (NN_name_calls.h). Remove this file once that suite includes 07_sampling_calls.h.
#pragma once

#include "07_sampling_calls.h"
