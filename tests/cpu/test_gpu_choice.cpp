// CPU tier: which EGL device a headless run opens (renderer/gl/gpu_choice.h), on made-up
// device lists like a GPU server's (a machine without a GPU cannot produce one).
#include <gtest/gtest.h>

#include "renderer/gl/gpu_choice.h"
#include "renderer/paths/turn_resolve_pass.h"
#include "renderer/renderer.h"

namespace npr {
namespace {

GpuDevice device(int index, std::string name, bool software, std::string node = "") {
  GpuDevice d;
  d.index = index;
  d.name = std::move(name);
  d.software = software;
  d.drmNode = std::move(node);
  return d;
}

// A server as NVIDIA's driver and Mesa list it together under libglvnd: Mesa's software device
// first, then two GPUs.
std::vector<GpuDevice> server() {
  return {device(0, "", true), device(1, "NVIDIA H100 80GB HBM3", false, "/dev/dri/renderD128"),
          device(2, "NVIDIA H100 80GB HBM3", false, "/dev/dri/renderD129")};
}

std::vector<int> order(const std::vector<GpuDevice>& devices, const std::string& request) {
  auto r = parseGpuRequest(request);
  EXPECT_TRUE(r) << r.error();
  auto o = devicesToTry(devices, *r);
  EXPECT_TRUE(o) << o.error();
  return o ? *o : std::vector<int>{};
}

TEST(GpuChoice, AutomaticTriesHardwareBeforeSoftwareKeepingEglOrder) {
  EXPECT_EQ(order(server(), "auto"), (std::vector<int>{1, 2, 0}));
  EXPECT_EQ(order(server(), ""), (std::vector<int>{1, 2, 0}));
  // Software devices in the middle and at the front: still after every hardware one.
  const std::vector<GpuDevice> mixed = {device(0, "", true), device(1, "Intel", false), device(2, "", true), device(3, "AMD", false)};
  EXPECT_EQ(order(mixed, "auto"), (std::vector<int>{1, 3, 0, 2}));
  // Only software (this machine): that device, then (by the caller) the surfaceless platform.
  EXPECT_EQ(order({device(0, "", true)}, "auto"), (std::vector<int>{0}));
  EXPECT_TRUE(order({}, "auto").empty());
}

TEST(GpuChoice, IndexAndNameChooseOnlyWhatTheyName) {
  EXPECT_EQ(order(server(), "2"), (std::vector<int>{2}));
  EXPECT_EQ(order(server(), "0"), (std::vector<int>{0}));
  EXPECT_EQ(order(server(), "nvidia"), (std::vector<int>{1, 2}));
  EXPECT_EQ(order(server(), "renderD129"), (std::vector<int>{2}));
  EXPECT_EQ(order(server(), "software"), (std::vector<int>{0}));
  EXPECT_EQ(order(server(), "HARDWARE"), (std::vector<int>{1, 2}));
}

TEST(GpuChoice, SurfacelessSkipsTheDeviceList) {
  auto r = parseGpuRequest("surfaceless");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->kind, GpuRequest::Kind::Surfaceless);
  auto o = devicesToTry(server(), *r);
  ASSERT_TRUE(o);
  EXPECT_TRUE(o->empty());
}

TEST(GpuChoice, UnknownDevicesAreRefusedWithTheList) {
  for (const char* request : {"3", "radeon"}) {
    auto r = parseGpuRequest(request);
    ASSERT_TRUE(r);
    auto o = devicesToTry(server(), *r);
    ASSERT_FALSE(o) << request;
    EXPECT_NE(o.error().find("matches none"), std::string::npos) << o.error();
    EXPECT_NE(o.error().find("1: NVIDIA H100 80GB HBM3 (/dev/dri/renderD128) [hardware]"), std::string::npos) << o.error();
  }
  auto none = devicesToTry({}, *parseGpuRequest("0"));
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().find("lists no devices"), std::string::npos) << none.error();
  EXPECT_FALSE(parseGpuRequest("-1"));
  // A name from the environment is escaped in the message.
  auto evil = devicesToTry(server(), *parseGpuRequest("\x1b]0;title\x07"));
  ASSERT_FALSE(evil);
  EXPECT_EQ(evil.error().find('\x1b'), std::string::npos);
}

TEST(GpuChoice, SoftwareRenderersAreRecognised) {
  EXPECT_TRUE(isSoftwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_TRUE(isSoftwareRenderer("softpipe"));
  EXPECT_TRUE(isSoftwareRenderer("Mesa X11 swrast"));
  EXPECT_FALSE(isSoftwareRenderer("NVIDIA H100 80GB HBM3/PCIe/SSE2"));
  EXPECT_FALSE(isSoftwareRenderer("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.6, DRM 3.49)"));
}

// The client extension strings as libglvnd answered them: with Mesa alone (this machine) and
// with NVIDIA's driver alone (an H100 server, driver 580), which names device enumeration only
// inside EGL_EXT_device_base. Missing that once left the GPU unlisted.
TEST(GpuChoice, DevicesAreListedUnderMesaAndUnderNvidiasClientExtensions) {
  const char* mesa = "EGL_EXT_device_base EGL_EXT_device_enumeration EGL_EXT_device_query EGL_EXT_platform_base "
                     "EGL_KHR_client_get_all_proc_addresses EGL_EXT_client_extensions EGL_KHR_debug EGL_EXT_platform_device "
                     "EGL_EXT_platform_wayland EGL_KHR_platform_wayland EGL_EXT_platform_x11 EGL_KHR_platform_x11 "
                     "EGL_EXT_platform_xcb EGL_MESA_platform_gbm EGL_KHR_platform_gbm EGL_MESA_platform_surfaceless";
  const char* nvidia = "EGL_EXT_platform_base EGL_EXT_device_base EGL_KHR_client_get_all_proc_addresses EGL_EXT_client_extensions "
                       "EGL_KHR_debug EGL_KHR_platform_x11 EGL_EXT_platform_x11 EGL_EXT_platform_device "
                       "EGL_MESA_platform_surfaceless EGL_EXT_explicit_device";
  EXPECT_TRUE(canEnumerateDevices(mesa));
  EXPECT_TRUE(canEnumerateDevices(nvidia));
  // Without the device platform a listed device cannot be opened; without either name there is
  // no list; a longer extension that merely starts with the name does not count.
  EXPECT_FALSE(canEnumerateDevices("EGL_EXT_device_base EGL_MESA_platform_surfaceless"));
  EXPECT_FALSE(canEnumerateDevices("EGL_EXT_platform_device EGL_EXT_device_query"));
  EXPECT_FALSE(canEnumerateDevices("EGL_EXT_device_base_v2 EGL_EXT_platform_device"));
  EXPECT_FALSE(canEnumerateDevices(nullptr));
  EXPECT_TRUE(hasEglExtension("A B C", "C"));
  EXPECT_FALSE(hasEglExtension("A B CD", "C"));
  EXPECT_FALSE(hasEglExtension("A B C", ""));
}

// A choice tuned on llvmpipe that a GPU reverses (bench_frames --turn-placements on an H100):
// dense meshes resolve their turned lookups after the mesh pass on a software rasterizer only.
TEST(DeviceTuning, TheTurnIsResolvedOnlyOnASoftwareRasterizerForDenseMeshes) {
  EXPECT_TRUE(resolveTurnAutomatically(true, 1.4f));    // the 871K torus at 1920x1080
  EXPECT_FALSE(resolveTurnAutomatically(true, 178.0f)); // the bunny
  EXPECT_FALSE(resolveTurnAutomatically(false, 1.4f));
  EXPECT_FALSE(resolveTurnAutomatically(false, 178.0f));
}

// Another (bench_animation on an H100): where the frame reads a deforming mesh on the CPU, a GPU
// poses it there too, so the CPU's copy is not uploaded; llvmpipe poses it on the CPU alone.
TEST(DeviceTuning, AutoPosesOnBothOnAGpuAndOnTheCpuAloneOnASoftwareRasterizer) {
  RenderSettings s;
  s.path = RenderPath::Triangle;  // reads the pose on the CPU
  PoseTargets soft = poseTargets(s, true), hard = poseTargets(s, false);
  EXPECT_TRUE(soft.cpu && !soft.gpu);
  EXPECT_TRUE(hard.cpu && hard.gpu);
  s.path = RenderPath::Pixel;  // reads it on the GPU only, wherever that is
  soft = poseTargets(s, true), hard = poseTargets(s, false);
  EXPECT_TRUE(soft.gpu && !soft.cpu);
  EXPECT_TRUE(hard.gpu && !hard.cpu);
  s.strokes.on = true;  // strokes are seeded on the CPU's pose
  EXPECT_TRUE(poseTargets(s, true).cpu && !poseTargets(s, true).gpu);
  EXPECT_TRUE(poseTargets(s, false).cpu && poseTargets(s, false).gpu);
  // The explicit choices hold on either.
  for (bool software : {true, false}) {
    s.deform = PosePlacement::Cpu;
    EXPECT_TRUE(poseTargets(s, software).cpu && !poseTargets(s, software).gpu);
    s.deform = PosePlacement::Gpu;
    EXPECT_TRUE(poseTargets(s, software).cpu && poseTargets(s, software).gpu);
    s.strokes.on = false;
    EXPECT_TRUE(!poseTargets(s, software).cpu && poseTargets(s, software).gpu);
    s.strokes.on = true;
  }
}

}  // namespace
}  // namespace npr
