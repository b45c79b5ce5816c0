// Internal to the image layer: the reader through which stb_image decodes untrusted bytes.
// Include it after <stb_image.h> with STB_IMAGE_IMPLEMENTATION (it needs stb's context to
// know the size of its refill buffer); each .cpp that decodes with stb has its own static
// copy of stb, and this reader is the same for all of them.
#pragma once

#ifndef STBI_INCLUDE_STB_IMAGE_H
#error "include <stb_image.h> (with its implementation) before image/stb_source.h"
#endif

#include <algorithm>
#include <cstddef>
#include <span>

namespace vkpt {

// stb_image reads through these callbacks so that a truncated file is noticed and cannot
// hang it: stb's own memory reader returns zeros past the end, and some decoders then
// report success on a truncated file. Past the end the reader hands stb `filler` bytes,
// chosen per decoder so that a decode which has run out of data ends, in an error or with
// ranOut set. The right filler depends on the format: a run-length count of 0 makes stb's
// HDR scanline loop spin forever (0xFF makes every run too long instead), while 0xFF is a
// JPEG fill byte that stb's marker search skips forever (0 ends it). stb refills a
// 128-byte buffer and otherwise asks for exactly the bytes it needs: a refill that finds
// nothing, or a short exact request, means the data ran out.
struct StbSource {
  std::span<const unsigned char> bytes;
  char filler = '\xff';
  size_t pos = 0;
  bool ranOut = false;

  static int Read(void* user, char* data, int size) {
    auto* s = static_cast<StbSource*>(user);
    const size_t n = std::min(size_t(size), s->bytes.size() - s->pos);
    std::copy_n(s->bytes.data() + s->pos, n, data);
    s->pos += n;
    if (n == size_t(size) || (n > 0 && size == sizeof(stbi__context::buffer_start))) return int(n);
    s->ranOut = true;
    std::fill(data + n, data + size, s->filler);
    return size;
  }
  static void Skip(void* user, int n) {
    auto* s = static_cast<StbSource*>(user);
    s->pos = std::min(s->bytes.size(), s->pos + size_t(std::max(n, 0)));
  }
  static int Eof(void* user) {
    auto* s = static_cast<StbSource*>(user);
    return s->pos >= s->bytes.size();
  }
  static constexpr stbi_io_callbacks kCallbacks{&Read, &Skip, &Eof};
};

}  // namespace vkpt
