// view_depth.frag: the depth prepass of --cascade-bounds depth. Each pixel the camera pass will
// shade gets the view depth of the surface it shows, measured as the camera pass measures it to
// pick a cascade (shared/pcf_shading.h pcfViewDepth, the same function on the same interpolated
// world position), or 0 where that surface receives no shadow; the target is cleared to 0 where
// nothing is drawn. The CPU reduces it to the smallest and largest (kernel/cascades.h
// visibleDepthRange). see: src/render/scene_renderer.cpp SceneRenderer::visibleDepths
in vec3 vPosWs;
in vec3 vNormalWs;

uniform int uReceives;   // 1: a receiver; 0: hides what is behind it, but is no receiver
uniform vec3 uEyeWs;     // the camera's eye and unit view direction (scene.frag's)
uniform vec3 uViewDirWs;

layout(location = 0) out float oViewDepth;

void main() { oViewDepth = uReceives != 0 ? pcfViewDepth(vPosWs, uEyeWs, uViewDirWs) : 0.0f; }
