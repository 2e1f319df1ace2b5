// Sanitizer settings for the CPU-tier test programs (the GL tier has its own in
// gl_test_env.cpp). Linked only into sanitizer-relevant binaries; empty otherwise.
#if defined(__SANITIZE_ADDRESS__)
// Full unwinding, so that suppressions can see frames inside third-party libraries.
extern "C" const char* __asan_default_options() { return "fast_unwind_on_malloc=0"; }
// OpenImageIO 2.4's PNG reader copies an error message in a libpng callback and then longjmps
// past its destructor when a PNG is truncated (test_palette reads one on purpose).
extern "C" const char* __lsan_default_suppressions() { return "leak:OpenImageIO_v2_4::PNGInput::PngReadCallback\n"; }
#endif
