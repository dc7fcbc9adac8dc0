// Strip: one circular (or open) band of bark transverse to the growth direction, a chain of
// quasi-rigid epidermis elements and soft fracture elements.
// Lefebvre & Neyret 2002, sec. 3.2.2 (strips model, Figure 5) and sec. 5.1 (attachment).
//
// Geometry along the strip is 1D arc length x (metres, measured on the substrate's current
// circumference). Element i spans [x[i], x[i+1]]; for a cyclic strip x[n] ≡ x[0] + C.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace phellem::bark {

using std::size_t;

enum class ElementKind : uint8_t { Epidermis, Fracture };

struct Element {
  ElementKind kind = ElementKind::Epidermis;
  // Refracture level: 0 = original epidermis; k > 0 = old fracture surface hardened into bark
  // (Lefebvre & Neyret 2001, sec. 4.1; 2002 Figure 9).
  uint8_t level = 0;
  int32_t fracture = -1;  // fracture elements: index into Strip::fractures (stable)
  // Fracture elements: copies of FractureElement::id / up / down kept next to the element, so
  // that the per-step scans and propagation need not visit the fracture records.
  int32_t id = -1, up = -1, down = -1;
  bool free_end() const { return up < 0 || down < 0; }
  double rest = 0;       // rest length l0 (m)
  double stiffness = 0;  // element stiffness K (epidermis: R·w/l0, sec. 5.3; fracture: K_f(l0))
  double threshold = 0;  // epidermis: jittered fracture threshold S_i on L/l0 (sec. 3.2.3)
};

static_assert(sizeof(Element) == 48, "the per-step passes stream every element: keep them small");

// What an element carries that the per-step passes do not read, kept apart (Strip::cold,
// index for index) so that the elements they stream through every step take 48 bytes
// instead of 64: a trunk's strips do not fit in this machine's caches, and each step reads
// them all (a gain of a few per cent at most on the benchmark trunk; see the README).
struct ElementCold {
  // Material coordinate of the element's left end on the unfractured epidermis, in [0, 1):
  // where UV0 of a break is read (sec. 3.3 "Texturing", 5.4).
  double material = 0;
  // Local strip width / nominal width where the element was made (sec. 5.3); elements keep
  // their place in the final (s, θ) space, so it is not looked up again.
  double width_factor = 1;
};

// How new material appears inside a fracture as it opens (sec. 3.3, Figure 13).
enum class OpeningMode : uint8_t { Axis, OneSide, Both };

// A fracture element's record in the fracture skeleton (sec. 3.2.4): links to the fracture
// elements it continues in the neighbouring strips, and its fracture id.
struct FractureElement {
  int32_t up = -1, down = -1;  // index into the next / previous strip's `fractures`
  int32_t id = -1;             // fracture (skeleton component) before merging; see FractureSkeleton
  int32_t birth = 0;           // step at which it appeared
  double uv0 = 0;              // material coordinate of the break on the epidermis, [0, 1)
  bool active = true;          // false once its surface hardened into bark (refracture)
};

struct Strip {
  bool cyclic = true;
  double circumference = 0;  // C: current substrate length of the strip (m)
  double width = 0;          // strip width w (m), along the growth axis
  std::vector<Element> elements;
  std::vector<ElementCold> cold;  // #elements on the strips of a StripModel (empty on a bare Strip)
  std::vector<double> x;          // #elements node positions (left end of each element); open strips: + right end
  std::vector<double> anchor;     // #nodes substrate locations a_i of the zero-rest-length springs (sec. 5.1)
  std::vector<double> attach;     // #nodes attachment stiffness K_a at each node
  std::vector<FractureElement> fractures;

  size_t size() const { return elements.size(); }
  size_t nodes() const { return cyclic ? elements.size() : elements.size() + 1; }
  // Right end of element i (wraps by C on cyclic strips).
  double right(size_t i) const { return i + 1 < x.size() ? x[i + 1] : (cyclic ? x[0] + circumference : x.back()); }
  double length(size_t i) const { return right(i) - x[i]; }
  // Total rest length of the epidermis elements of level 0 (the original epidermis; the
  // paper's first observation: it is conserved).
  double original_epidermis() const;
};

}  // namespace phellem::bark
