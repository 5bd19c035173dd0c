#include "glint/math/transform.h"

#include <gtest/gtest.h>

TEST(Transform, Identity) { EXPECT_TRUE(glint::Transform().is_identity()); }
