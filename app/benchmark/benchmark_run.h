// `npr-viewer --benchmark`: the speed/accuracy trade of every render path, measured on a
// scripted camera and light motion against a reference computed independently of all paths
// (eye-space position and normal per pixel, lit on the CPU in double precision). Writes
// results.csv, results.md and one plot per configuration (gnuplot) into --out.
#pragma once

#include "app/cli.h"

namespace npr {

int runBenchmark(const Options& options);

}  // namespace npr
