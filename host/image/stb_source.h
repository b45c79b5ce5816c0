// Internal to the image layer: the reader through which stb_image decodes untrusted bytes,
// and the heap its decodes allocate from. Include it before <stb_image.h> with
// STB_IMAGE_IMPLEMENTATION: it routes stb's allocations to StbHeap. Each .cpp that
// decodes with stb has its own static copy of stb; this reader is the same for all.
#pragma once

#ifdef STBI_INCLUDE_STB_IMAGE_H
#error "include image/stb_source.h before <stb_image.h>"
#endif

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <span>
#include <vector>

namespace vkpt::internal {

// Every block stb allocates while a StbHeap is the thread's current one is freed with it,
// whether stb returned (its pixels included: copy them out first) or the reader ended the
// decode with StbEndOfData thrown through stb.
class StbHeap {
 public:
  StbHeap() : outer_(current) { current = this; }
  ~StbHeap() {
    current = outer_;
    for (void* p : blocks_) std::free(p);
  }
  StbHeap(const StbHeap&) = delete;
  StbHeap& operator=(const StbHeap&) = delete;

  static void* Malloc(size_t size) { return Keep(std::malloc(size)); }
  static void* Realloc(void* p, size_t size) {
    Forget(p);  // before: p may not be read after realloc
    void* q = std::realloc(p, size);
    Keep(q ? q : p);  // a failed realloc leaves p allocated
    return q;
  }
  static void Free(void* p) {
    Forget(p);
    std::free(p);
  }

 private:
  static void* Keep(void* p) {
    if (p && current) current->blocks_.push_back(p);
    return p;
  }
  static void Forget(void* p) {
    if (!p || !current) return;
    std::vector<void*>& b = current->blocks_;
    if (auto it = std::find(b.rbegin(), b.rend(), p); it != b.rend()) b.erase(std::next(it).base());
  }
  static inline thread_local StbHeap* current = nullptr;
  StbHeap* outer_;
  std::vector<void*> blocks_;
};

// Thrown by StbSource::Read when stb asks for bytes past the end of the data.
struct StbEndOfData {};

// The reader stb_image decodes through. It hands stb the bytes that exist and nothing
// else, and reports their end truthfully (Eof). stb's own answer to a read that finds
// nothing is to go on with zeros forever, which some of its loops never leave (a
// Radiance run-length count of 0 makes no progress), so a request that cannot be met in
// full ends the decode instead: Read throws StbEndOfData, and with it every read loop
// stb runs is bounded by the bytes that exist. stb refills a 128-byte buffer and
// otherwise asks for exactly the bytes it needs: a short refill is the data's last bytes
// (stb asks again only when it needs more), a short exact request is the data running out.
struct StbSource {
  std::span<const unsigned char> bytes;
  size_t pos = 0;

  static int Read(void* user, char* data, int size) {
    auto* s = static_cast<StbSource*>(user);
    const size_t n = std::min(size_t(std::max(size, 0)), s->bytes.size() - s->pos);
    if (n < size_t(size) && (n == 0 || size != kRefillSize)) throw StbEndOfData{};
    std::copy_n(s->bytes.data() + s->pos, n, data);
    s->pos += n;
    return int(n);
  }
  static void Skip(void* user, int n) {
    auto* s = static_cast<StbSource*>(user);
    s->pos = std::min(s->bytes.size(), s->pos + size_t(std::max(n, 0)));
  }
  static int Eof(void* user) {
    auto* s = static_cast<StbSource*>(user);
    return s->pos >= s->bytes.size();
  }
  // sizeof(stbi__context::buffer_start): each file that includes stb checks it.
  static constexpr int kRefillSize = 128;
};

}  // namespace vkpt::internal

#define STBI_MALLOC(size) ::vkpt::internal::StbHeap::Malloc(size)
#define STBI_REALLOC(p, size) ::vkpt::internal::StbHeap::Realloc(p, size)
#define STBI_FREE(p) ::vkpt::internal::StbHeap::Free(p)
