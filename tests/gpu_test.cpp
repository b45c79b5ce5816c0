#include "gpu_test.h"

#include <memory>

namespace vkpt::internal::test {

vk::Context& Gpu() {
  static std::unique_ptr<vk::Context> ctx = [] {
    vk::ContextOptions o;
    o.validation = true;
    return std::make_unique<vk::Context>(o);
  }();
  return *ctx;
}

}  // namespace vkpt::internal::test
