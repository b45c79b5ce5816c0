// Linked into every executable of a VKPT_SANITIZE build with AddressSanitizer only
// (cmake/Sanitizers.cmake); never into a normal build.
//
// dlclose() becomes a no-op, so the libraries the Vulkan loader opens and closes again
// (the lavapipe driver, the validation layer) stay mapped until the process exits, when
// LeakSanitizer checks. Unmapped, the heap blocks their globals point to look leaked, and
// the stacks of those allocations name no module or the wrong one, so no suppression by
// library could match them. Mapped, their reachable memory is not reported, and what
// they truly leak is named, and suppressed by library name in lsan.supp.
// Exported explicitly: the build's hidden visibility would keep it inside the executable,
// where the loader's calls would not reach it.
extern "C" __attribute__((visibility("default"))) int dlclose(void*) { return 0; }
