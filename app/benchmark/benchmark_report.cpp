// The benchmark's files: results.csv, results.md and the speed/accuracy plots (see
// benchmark_results.h).
#include "app/benchmark/benchmark_results.h"
#include "renderer/settings/choice_names.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace npr {
namespace fs = std::filesystem;
namespace {

std::string fmt(double v, int digits = 3) {
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", digits, v);
  return b;
}

std::string slug(const std::string& s) {
  std::string o;
  for (char c : s) o += std::isalnum(static_cast<unsigned char>(c)) ? char(std::tolower(static_cast<unsigned char>(c))) : '-';
  return o;
}

}  // namespace

void writeBenchmarkReport(const std::vector<ConfigResult>& results, const fs::path& dir, glm::ivec2 size, int frames,
                          const std::string& gl) {
  std::ofstream csv(dir / "results.csv");
  csv << "model,palette,match,path,frames,width,height,median_ms,p95_ms,cpu_ms,gpu_ms,x_reference,error_unit,mean_error,p95_error,"
         "max_error,index_mismatch_share,jump_share,pop_share,nonfinite\n";
  std::ofstream md(dir / "results.md");
  md << "Measured on " << gl << ", " << size.x << "x" << size.y << ", " << frames
     << " frames of a scripted light and camera orbit per path.\n\n";
  for (const ConfigResult& c : results) {
    md << "### " << c.model << ", " << c.palette << ", match " << choiceName(c.mode) << "\n\n";
    md << "| path | median ms | p95 ms | CPU ms | x reference | mean error | p95 error | max error | index differs | jumps > 1 step | pops |\n";
    md << "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const PathResult& p : c.paths) {
      const bool hasAccuracy = p.pixels > 0;
      const double mismatch = hasAccuracy ? double(p.mismatched) / double(p.pixels) : 0.0;
      const double jump = p.compared ? double(p.jumps) / double(p.compared) : 0.0;
      const double pop = p.compared ? double(p.pops) / double(p.compared) : 0.0;
      csv << '"' << c.model << "\",\"" << c.palette << "\"," << choiceName(c.mode) << ',' << renderPathName(p.path) << ',' << frames
          << ',' << size.x << ',' << size.y << ',' << fmt(p.medianMs) << ',' << fmt(p.p95Ms) << ',' << fmt(p.cpuMs) << ','
          << fmt(p.gpuMs) << ',' << fmt(p.xReference) << ',' << c.errorUnit << ',';
      if (hasAccuracy) csv << fmt(p.error.mean(), 5) << ',' << fmt(p.error.p95(), 5) << ',' << fmt(p.error.max(), 5) << ',' << fmt(mismatch, 5);
      else csv << ",,,";
      csv << ',' << fmt(jump, 5) << ',' << fmt(pop, 5) << ',' << c.nonFinite << '\n';
      md << "| " << renderPathName(p.path) << " | " << fmt(p.medianMs, 1) << " | " << fmt(p.p95Ms, 1) << " | " << fmt(p.cpuMs, 1) << " | "
         << fmt(p.xReference, 2) << " | ";
      if (hasAccuracy)
        md << fmt(p.error.mean(), 4) << " | " << fmt(p.error.p95(), 4) << " | " << fmt(p.error.max(), 3) << " | " << fmt(100 * mismatch, 2)
           << "% | " << fmt(100 * jump, 3) << "% | " << fmt(100 * pop, 3) << "% |\n";
      else
        md << "- | - | - | - | - | - |\n";
    }
    md << "\nError unit: " << c.errorUnit << ". Static frames (nothing changed): " << c.staticRecomputes << " lighting recomputations, "
       << c.staticUploads << " uploads, " << c.staticBuilds << " shader builds over " << c.staticFrames
       << " frames. Pixel path, one directional light without specular: " << fmt(c.lightMinimalMs, 1)
       << " ms; four lights with specular, spots and attenuation: " << fmt(c.lightFullMs, 1) << " ms. Non-finite values: " << c.nonFinite
       << ".\n\n";

    // The plot: frame time against mean error, one labelled point per path.
    const std::string stem = "plot-" + slug(c.model) + "-" + slug(c.palette) + "-" + choiceName(c.mode);
    std::ofstream data(dir / (stem + ".dat"));
    for (const PathResult& p : c.paths)
      if (p.pixels > 0) data << renderPathName(p.path) << ' ' << p.medianMs << ' ' << p.error.mean() << '\n';
    data.close();
    std::ofstream gp(dir / (stem + ".gp"));
    gp << "set terminal pngcairo size 900,600 noenhanced\nset output '" << (dir / (stem + ".png")).string() << "'\n"
        << "set title '" << c.model << ", " << c.palette << ", match " << choiceName(c.mode) << " (" << size.x << "x" << size.y
        << ")'\nset xlabel 'median frame time (ms)'\nset ylabel 'mean error (" << c.errorUnit << ")'\n"
        << "set grid\nset key outside right title 'path'\nset offsets graph 0.15, graph 0.15, graph 0.15, graph 0.15\n";
    // The plain lit render's frame time, for scale: a dashed vertical line.
    for (const PathResult& p : c.paths)
      if (p.path == RenderPath::Reference && p.medianMs > 0)
        gp << "set arrow from " << p.medianMs << ", graph 0 to " << p.medianMs << ", graph 1 nohead dashtype 2\n"
           << "set label 'reference' at " << p.medianMs << ", graph 0.95 offset 0.5, 0\n";
    gp << "plot ";
    int k = 0;
    for (const PathResult& p : c.paths) {
      if (p.pixels == 0) continue;
      gp << (k ? ", " : "") << "'" << (dir / (stem + ".dat")).string() << "' using (strcol(1) eq '" << renderPathName(p.path)
          << "' ? $2 : 1/0):3 with points pointsize 2.5 pointtype " << (k + 5) << " title '" << renderPathName(p.path) << "'";
      ++k;
    }
    gp << "\n";
    gp.close();
    const std::string cmd = "gnuplot '" + (dir / (stem + ".gp")).string() + "' 2>&1";
    if (std::system(cmd.c_str()) != 0) std::fprintf(stderr, "npr-viewer: gnuplot failed for %s (is gnuplot installed?)\n", stem.c_str());
    md << "![" << stem << "](" << stem << ".png)\n\n";
  }
}

}  // namespace npr
