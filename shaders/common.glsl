// Shared by every stage: the C++ lerp (a + t·(b − a)), kept as written.
float mix_exact(float t, float a, float b) { return a + t * (b - a); }
// The bark of the object drawn, fixed when the program is compiled (one program per kind, so
// llvmpipe never runs the other kinds' code under a mask): 0 none, 1 cracks (stress), 2 a
// fracture field (strips); BARK_TINTS 1 when stress bark varies its colour per plate and crack;
// IMAGE_DISPLACEMENT 1 when an image displacement adds to the bark's offset.
#ifndef BARK_KIND
#define BARK_KIND 0
#endif
#ifndef BARK_TINTS
#define BARK_TINTS 0
#endif
#ifndef IMAGE_DISPLACEMENT
#define IMAGE_DISPLACEMENT 0
#endif
