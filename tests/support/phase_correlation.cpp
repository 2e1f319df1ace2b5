// Phase correlation (see phase_correlation.h). The transforms are plain separable DFTs: the
// windows are small (64-128 pixels) and a test runs a handful, so O(n^3) costs milliseconds and
// needs no FFT library.
#include "support/phase_correlation.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

namespace npr::test {
namespace {

using Complex = std::complex<double>;

// In place over an n x n row-major grid: rows, then columns; `sign` -1 forward, +1 inverse
// (unscaled: the peak's position is all that is read).
void dft2(std::vector<Complex>& g, int n, int sign) {
  const double pi = 3.14159265358979323846;
  std::vector<Complex> twiddle(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) twiddle[static_cast<std::size_t>(k)] = std::polar(1.0, sign * 2.0 * pi * k / n);
  std::vector<Complex> line(static_cast<std::size_t>(n)), out(static_cast<std::size_t>(n));
  for (int pass = 0; pass < 2; ++pass)
    for (int i = 0; i < n; ++i) {
      auto at = [&](int j) -> Complex& { return g[pass == 0 ? std::size_t(i) * n + j : std::size_t(j) * n + i]; };
      for (int j = 0; j < n; ++j) line[static_cast<std::size_t>(j)] = at(j);
      for (int k = 0; k < n; ++k) {
        Complex s = 0.0;
        for (int j = 0, t = 0; j < n; ++j, t = t + k >= n ? t + k - n : t + k)  // t = k j mod n
          s += line[static_cast<std::size_t>(j)] * twiddle[static_cast<std::size_t>(t)];
        out[static_cast<std::size_t>(k)] = s;
      }
      for (int j = 0; j < n; ++j) at(j) = out[static_cast<std::size_t>(j)];
    }
}

std::vector<Complex> windowed(const ImageRGBA8& img, int x0, int y0, int n) {
  const double pi = 3.14159265358979323846;
  std::vector<double> lum(std::size_t(n) * n);
  double mean = 0.0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const std::uint8_t* p = &img.pixels[(std::size_t(y0 + y) * img.width + std::size_t(x0 + x)) * 4];
      mean += lum[std::size_t(y) * n + x] = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    }
  mean /= double(n) * n;
  std::vector<Complex> g(lum.size());
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double w = (0.5 - 0.5 * std::cos(2.0 * pi * (x + 0.5) / n)) * (0.5 - 0.5 * std::cos(2.0 * pi * (y + 0.5) / n));
      g[std::size_t(y) * n + x] = (lum[std::size_t(y) * n + x] - mean) * w;
    }
  return g;
}

}  // namespace

glm::vec2 phaseCorrelationShift(const ImageRGBA8& a, const ImageRGBA8& b, int x0, int y0, int n) {
  const double pi = 3.14159265358979323846;
  const std::vector<Complex> fa = [&] { auto g = windowed(a, x0, y0, n); dft2(g, n, -1); return g; }();
  auto transformed = [&](int x, int y) { auto g = windowed(b, x, y, n); dft2(g, n, -1); return g; };
  // The whole-pixel shift: where the normalised cross-power spectrum's inverse peaks.
  std::vector<Complex> r = transformed(x0, y0);
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Complex c = r[i] * std::conj(fa[i]);  // |A|^2 e^(-2 pi i k.d / n) for b(p) = a(p - d)
    r[i] = std::abs(c) > 1e-12 ? c / std::abs(c) : Complex(0.0);
  }
  dft2(r, n, +1);
  std::size_t best = 0;
  for (std::size_t i = 1; i < r.size(); ++i)
    if (r[i].real() > r[best].real()) best = i;
  auto signedIndex = [&](int k) { return k >= n / 2 ? k - n : k; };
  const int px = signedIndex(int(best % std::size_t(n))), py = signedIndex(int(best / std::size_t(n)));
  // The rest from b's window moved by that shift, so what is left is under a pixel and the
  // window, which stays put while the content moves, biases it little: the slope of the
  // cross-power spectrum's phase over the lower half of the band (where it cannot wrap),
  // least squares weighted by the spectrum's magnitude.
  const int bx0 = std::clamp(x0 + px, 0, b.width - n), by0 = std::clamp(y0 + py, 0, b.height - n);
  const std::vector<Complex> fb = transformed(bx0, by0);
  double sxx = 0.0, sxy = 0.0, syy = 0.0, gx = 0.0, gy = 0.0;
  const int band = n / 4;
  for (int ky = -band; ky <= band; ++ky)
    for (int kx = -band; kx <= band; ++kx) {
      if (kx == 0 && ky == 0) continue;
      const std::size_t i = std::size_t((ky + n) % n) * n + std::size_t((kx + n) % n);
      const Complex c = fb[i] * std::conj(fa[i]);
      const double w = std::abs(c), phase = std::arg(c);
      sxx += w * kx * kx, sxy += w * kx * ky, syy += w * ky * ky;
      gx += w * kx * phase, gy += w * ky * phase;
    }
  const double det = sxx * syy - sxy * sxy;
  if (!(std::fabs(det) > 0.0)) return {float(bx0 - x0), float(by0 - y0)};
  const double scale = -double(n) / (2.0 * pi);
  return {float(bx0 - x0 + scale * (syy * gx - sxy * gy) / det), float(by0 - y0 + scale * (sxx * gy - sxy * gx) / det)};
}

}  // namespace npr::test
