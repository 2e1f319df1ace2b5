// Shared by the benchmarks: the generated large mesh (871,200 triangles) and its OBJ file,
// written once into the system temp folder.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "renderer/gl/headless_context.h"

#include "renderer/mesh/mesh.h"

namespace npr::bench {

constexpr int kTorusSide = 660;  // 2 x 660 x 660 = 871,200 triangles

const Mesh& largeMesh();
// The large mesh as an OBJ file (about 33 MB), generated on first use.
const std::string& largeObjPath();
// The large mesh with an appearance, loaded through the OBJ loader from files written once into
// the temp folder: 16 materials by region (4 of them with a 512x512 diffuse map) and spherical
// texture coordinates.
const Mesh& largeMaterialMesh();
// The image benchmarks' shared options: --size WxH, --frames N, --quick. Prints the usage
// line naming `program` and returns nothing on anything else.
struct ImageBenchArgs {
  int width = 640, height = 480, frames = 24;
  bool quick = false;
  int objects = 0;  // --objects N: the scene's object count, where a bench builds one (0: its own)
};
std::optional<ImageBenchArgs> parseImageBenchArgs(int argc, char** argv, const char* program);
// The headless context on the device NPR_GPU names (as the viewer's --gpu), without the debug
// callback; on failure prints why and returns null with the exit status to end with (2: a bad
// NPR_GPU, 1: no context).
std::unique_ptr<HeadlessContext> openBenchContext(int& exitStatus);
// Peak resident memory of this process so far, in MiB.
double peakRssMiB();

}  // namespace npr::bench
