// GTEST_FLAG_SET, which GoogleTest has from 1.12 on, for 1.11 (Ubuntu 22.04's).
#pragma once

#include <gtest/gtest.h>

#ifndef GTEST_FLAG_SET
#define GTEST_FLAG_SET(name, value) (void)(::testing::GTEST_FLAG(name) = value)
#endif
