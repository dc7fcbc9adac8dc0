#include "compare/skeleton.h"

#include <tbb/parallel_for.h>

#include <stdexcept>

namespace phellem {

// Zhang & Suen 1984: alternate two sub-iterations until neither deletes a pixel. With the
// neighbours P2..P9 clockwise from north, a foreground pixel is deleted when
//   2 ≤ B(P1) ≤ 6 (foreground neighbours), A(P1) = 1 (0→1 transitions in P2..P9,P2), and
//   sub-iteration 1: P2·P4·P6 = 0 and P4·P6·P8 = 0;  sub-iteration 2: P2·P4·P8 = 0 and P2·P6·P8 = 0.
// Each sub-iteration decides every deletion on the image as it was before it (parallel).
std::vector<uint8_t> zhang_suen_skeleton(const std::vector<uint8_t>& mask, int width, int height) {
  if (mask.size() != size_t(width) * size_t(height)) throw std::invalid_argument("zhang_suen_skeleton: size mismatch");
  // One pixel of background padding all round, as the paper's pattern is framed by 0s.
  const int pw = width + 2, ph = height + 2;
  std::vector<uint8_t> img(size_t(pw) * size_t(ph), 0);
  std::vector<int> fg;  // padded indices of the remaining foreground pixels
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (mask[size_t(y) * size_t(width) + size_t(x)]) {
        const int i = (y + 1) * pw + (x + 1);
        img[size_t(i)] = 1;
        fg.push_back(i);
      }
  std::vector<uint8_t> del(fg.size());
  for (bool changed = true; changed;) {
    changed = false;
    for (int step = 0; step < 2; ++step) {
      del.assign(fg.size(), 0);
      tbb::parallel_for(tbb::blocked_range<size_t>(0, fg.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t n = r.begin(); n < r.end(); ++n) {
          const uint8_t* c = &img[size_t(fg[n])];
          // P2 (north), P3, P4 (east), P5, P6 (south), P7, P8 (west), P9
          const int p[8] = {c[-pw], c[-pw + 1], c[1], c[pw + 1], c[pw], c[pw - 1], c[-1], c[-pw - 1]};
          const int B = p[0] + p[1] + p[2] + p[3] + p[4] + p[5] + p[6] + p[7];
          if (B < 2 || B > 6) continue;
          int A = 0;
          for (int k = 0; k < 8; ++k) A += p[k] == 0 && p[(k + 1) & 7] == 1;
          if (A != 1) continue;
          const int P2 = p[0], P4 = p[2], P6 = p[4], P8 = p[6];
          const bool ok = step == 0 ? (P2 * P4 * P6 == 0 && P4 * P6 * P8 == 0) : (P2 * P4 * P8 == 0 && P2 * P6 * P8 == 0);
          del[n] = ok;
        }
      });
      size_t kept = 0;
      for (size_t n = 0; n < fg.size(); ++n) {
        if (del[n]) {
          img[size_t(fg[n])] = 0;
          changed = true;
        } else {
          fg[kept++] = fg[n];
        }
      }
      fg.resize(kept);
    }
  }
  std::vector<uint8_t> out(mask.size(), 0);
  for (int i : fg) out[size_t(i / pw - 1) * size_t(width) + size_t(i % pw - 1)] = 1;
  return out;
}

}  // namespace phellem
