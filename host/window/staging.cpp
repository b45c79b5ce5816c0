#include "window/staging.h"

namespace vkpt::internal {

StagingImage::StagingImage(const PresentDevice& device, uint32_t width, uint32_t height)
    : device_(device), width_(width), height_(height) {
  const VkDevice d = device.Device();
  try {
    VkBufferCreateInfo bufferInfo{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bufferInfo.size = VkDeviceSize(width) * height * 4;
    bufferInfo.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    bufferInfo.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VKPT_VK_CHECK(vkCreateBuffer(d, &bufferInfo, nullptr, &buffer_));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(d, buffer_, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = device.MemoryType(
        req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    VKPT_VK_CHECK(vkAllocateMemory(d, &alloc, nullptr, &bufferMemory_));
    VKPT_VK_CHECK(vkBindBufferMemory(d, buffer_, bufferMemory_, 0));
    void* mapped = nullptr;
    VKPT_VK_CHECK(vkMapMemory(d, bufferMemory_, 0, VK_WHOLE_SIZE, 0, &mapped));
    mapped_ = static_cast<uint8_t*>(mapped);

    VkImageCreateInfo imageInfo{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    imageInfo.imageType = VK_IMAGE_TYPE_2D;
    imageInfo.format = kFormat;
    imageInfo.extent = {width, height, 1};
    imageInfo.mipLevels = 1;
    imageInfo.arrayLayers = 1;
    imageInfo.samples = VK_SAMPLE_COUNT_1_BIT;
    imageInfo.tiling = VK_IMAGE_TILING_OPTIMAL;
    imageInfo.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    imageInfo.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    imageInfo.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VKPT_VK_CHECK(vkCreateImage(d, &imageInfo, nullptr, &image_));
    vkGetImageMemoryRequirements(d, image_, &req);
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = device.MemoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VKPT_VK_CHECK(vkAllocateMemory(d, &alloc, nullptr, &imageMemory_));
    VKPT_VK_CHECK(vkBindImageMemory(d, image_, imageMemory_, 0));
  } catch (...) {
    Release();
    throw;
  }
}

StagingImage::~StagingImage() { Release(); }

// Called only when the device no longer uses the objects (Presenter waits for its fence).
void StagingImage::Release() {
  const VkDevice d = device_.Device();
  if (image_) vkDestroyImage(d, image_, nullptr);
  if (imageMemory_) vkFreeMemory(d, imageMemory_, nullptr);
  if (buffer_) vkDestroyBuffer(d, buffer_, nullptr);
  if (bufferMemory_) vkFreeMemory(d, bufferMemory_, nullptr);  // unmaps it too
  image_ = VK_NULL_HANDLE, imageMemory_ = VK_NULL_HANDLE, buffer_ = VK_NULL_HANDLE, bufferMemory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
}

}  // namespace vkpt::internal
