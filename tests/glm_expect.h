// glm_expect.h: GoogleTest checks for GLM vectors, component by component.
#pragma once

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#define EXPECT_VEC3_NEAR(a, b, tol)     \
    do {                                \
        glm::vec3 va_ = (a);            \
        glm::vec3 vb_ = (b);            \
        EXPECT_NEAR(va_.x, vb_.x, tol); \
        EXPECT_NEAR(va_.y, vb_.y, tol); \
        EXPECT_NEAR(va_.z, vb_.z, tol); \
    } while (0)
