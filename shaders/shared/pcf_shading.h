// pcf_shading.h: the camera pass's display encoding, in the subset of C++ and GLSL that
// pcf_kernel.h is written in (after pcf_prelude.h). Not PCF: the picture's gamma, shared so that
// a C++ test can bound the very function the fragment shader runs.
// see: shaders/scene.frag (the caller), src/kernel/shading.h (C++), tests/shading_test.cpp

// Gamma 2.2, encode: g(x) = x^(1/2.2) for the scene's light factor x in [0.25, 1] (ambient 0.25
// to full sun; scene.frag). The exponent is the conventional display gamma of "GPU Gems 3,
// Chapter 24: The Importance of Being Linear" (Gritz and d'Eon, 2007).
// A pow() is log2 and exp2, each a long polynomial on llvmpipe; this is one sqrt and a degree-4
// polynomial (pcfscope's own fit, interpolation at the 5 Chebyshev nodes of [0.5, 1]):
//   s = sqrt(x) in [0.5, 1],   x^(1/2.2) = s^(1/1.1) = s * s^(-1/11),   s^(-1/11) ~ q(s)
//   q(s) = c0 + c1 s + c2 s^2 + c3 s^3 + c4 s^4 (Horner)
// |g(x) - x^(1/2.2)| <= 6e-6 on [0.25, 1] (tests/shading_test.cpp), 0.0015 of one 8-bit step.
PCF_FN float pcfGammaEncode(float x) {
    float s = sqrt(x);
    float q = 0.0957764306f;
    q = q * s - 0.379465962f;
    q = q * s + 0.620897234f;
    q = q * s - 0.5769154f;
    q = q * s + 1.2397127f;
    return s * q;
}
