// Shared by every stage: the C++ lerp (a + t·(b − a)), kept as written.
float mix_exact(float t, float a, float b) { return a + t * (b - a); }
uniform int bark_kind;  // 0 none, 1 cracks (stress), 2 fracture field (strips)
