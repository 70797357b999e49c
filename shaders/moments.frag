// moments.frag: the moments pass (issue 33). Each texel of the moments map is the weighted mean
// of the moments of the N x N depths around it: pcfMomentsTexel of the shared kernel, the code
// the CPU runs for the trace (kernel/moments.h). The target is RG or RGBA, 16F or 32F: the
// method's texel kind (kernel/methods.cpp mapTexelKind). The loader puts the prelude, the kernel
// and the parameter uniforms (pcfProgramParams) before this file; PCF_METHOD, PCF_KERNEL and
// PCF_WEIGHTS arrive as defines. uPcfDepth is the light's depth map behind the nearest sampler.
// see: src/render/scene_renderer.cpp (renderMomentsPass)
uniform sampler2D uPcfDepth;
layout(location = 0) out vec4 oMoments;

void main() {
    oMoments = pcfMomentsTexel(uPcfDepth, ivec2(gl_FragCoord.xy), pcfProgramParams(vec2(1.0f, 0.0f)));
}
