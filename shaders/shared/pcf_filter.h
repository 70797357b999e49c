// pcf_filter.h: the shared kernel's entry points, pcfFilterRef (the dispatch over every method)
// and pcfFilter, in the subset of C++ and GLSL that pcf_kernel.h is written in. It comes last,
// after pcf_kernel.h, pcf_disk.h and pcf_moments.h, whose methods it dispatches to.

// The entry point with a bias mode: visibility of a receiver seen at uv, compared per tap as
// ref (PcfRef) says. Weighted sums can land an ulp above 1; the result is clamped to [0,1].
// The ref every method's taps see: under receiver-plane bias, the plane's slope capped.
PCF_FN PcfRef pcfLookupRef(PcfRef ref) {
    if (ref.bias.mode == PCF_BIAS_RECEIVER_PLANE) {
        ref.bias.dzduv = pcfClampDzDuv(ref.bias.dzduv, ref.bias.rpdbMax);
    }
    return ref;
}

PCF_MAP_FN float pcfFilterRef(Map map, vec2 uv, PcfRef lookupRef, PcfParams prm) {
    PcfRef ref = pcfLookupRef(lookupRef);
    float v;
    if (prm.method == PCF_NEAREST) {
        v = pcfNearest(map, uv, ref, 1.0f);
    } else if (prm.method == PCF_BOX2X2) {
        v = pcfBox2x2(map, uv, ref);
    } else if (prm.method == PCF_BILINEAR2X2) {
        v = pcfBilinearLookup(map, uv, ref, 1.0f);
    } else if (prm.method == PCF_HW2X2) {
        v = pcfHwTap(map, uv, ref, 1.0f);
    } else if (prm.method == PCF_NAIVE && prm.weights != PCF_WEIGHTS_BOX) {
        v = pcfNaiveWeighted(map, uv, ref, prm.kernel, prm.weights, prm.sigma);
    } else if (prm.method == PCF_NAIVE) {
        v = pcfNaive(map, uv, ref, prm.kernel);
    } else if (prm.method == PCF_GATHER && prm.weights != PCF_WEIGHTS_BOX) {
        v = pcfGatherWeighted(map, uv, ref, prm.kernel, prm.weights, prm.sigma);
    } else if (prm.method == PCF_GATHER) {
        v = pcfGather(map, uv, ref, prm.kernel);
    } else if (prm.method == PCF_HW) {
        v = pcfHw(map, uv, ref, prm.kernel);
    } else if (prm.method == PCF_TENT) {
        v = pcfTent(map, uv, ref, prm.kernel);
    } else if (prm.method == PCF_POISSON) {
        v = pcfPoisson(map, uv, ref, prm.radius, prm.rotation);
    } else if (prm.method == PCF_PCSS) {
        v = pcfPcss(map, uv, ref, prm);
    } else if (prm.method >= PCF_VSM && prm.method <= PCF_MSM_HAUSDORFF) {
        v = pcfMomentEstimate(map, uv, ref.ref, prm).visibility;
    } else {
        // A method this dispatch does not know: no other method's answer, but a value that no
        // visibility takes, returned unclamped (tests/methods_test.cpp and gpu_parity_test.cpp
        // run every method of the table through this dispatch and look for it).
        return PCF_UNDISPATCHED;
    }
    return clamp(v, 0.0f, 1.0f);
}

// The one entry point without a per-tap bias: visibility of a receiver at depth ref (after
// bias) seen at uv, every tap compared with the same ref.
PCF_MAP_FN float pcfFilter(Map map, vec2 uv, float ref, PcfParams prm) {
    return pcfFilterRef(map, uv, pcfPlainRef(ref, uv), prm);
}
