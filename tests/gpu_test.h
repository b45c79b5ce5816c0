// The one validated Vulkan context every GPU test of the program shares, and the fixture
// that ends each GPU test by asserting the validation layer reported nothing.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>

#include "vk/context.h"

namespace vkpt::test {

// Created on first use (device creation costs ~100 ms), with the validation layer on.
vk::Context& Gpu();

class ValidatedGpuTest : public ::testing::Test {
 protected:
  void TearDown() override {
    EXPECT_EQ(Gpu().ValidationMessages(), before_) << "the Vulkan validation layer reported messages";
  }
  uint32_t before_ = Gpu().ValidationMessages();
};

}  // namespace vkpt::test
