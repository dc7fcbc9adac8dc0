// The power spectrum of a raster in octave bands of cycles/cm (the lit statistics, issue 44 item 2).
#pragma once

#include <cstdint>
#include <vector>

namespace phellem {

// One octave [lo, hi) of radial frequency, hi = 2·lo, both powers of two in cycles/cm.
struct SpectrumBand {
  double lo_cycles_per_cm = 0, hi_cycles_per_cm = 0;
  double share = 0;  // the band's power over the power of every band listed (Σ share = 1)
};

// The lowest octave starts at this many cycles across the shorter side at least. Its half-plane
// annulus then holds ≈ (3π/2)·kMinCyclesAcross² ≈ 300 DFT bins, so the band power of a random
// texture is estimated to about 1/√300 ≈ 6 % (two crops of one bark differed by 40 % in an
// octave starting at 5 cycles across, measured with a Hann window).
inline constexpr double kMinCyclesAcross = 8;

// The bands measured on a `width` × `height` raster at `px_per_cm`: every octave 2^k ≤ f < 2^(k+1)
// cycles/cm with 2^k ≥ kMinCyclesAcross/(the shorter side in cm) and 2^(k+1) ≤ the Nyquist
// frequency px_per_cm/2. Ascending; empty when no octave fits.
std::vector<SpectrumBand> octave_bands(int width, int height, double px_per_cm);

// `values` (height × width, row-major) with the valid pixels `valid` (same size; empty = all)
// → octave_bands with their power shares. The valid values, minus their window-weighted mean,
// times a separable Tukey window (cosine tapers over 1/8 of each side), masked pixels 0, zero-padded to a 2·3·5-smooth size, go
// through Eigen's FFT (kissfft); power at radius f = |(kx/W', ky/H')|·px_per_cm is summed per
// band. All shares 0 when there is no power (a constant image).
std::vector<SpectrumBand> octave_band_power(const std::vector<float>& values, const std::vector<uint8_t>& valid, int width,
                                            int height, double px_per_cm);

}  // namespace phellem
