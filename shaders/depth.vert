// depth.vert: the shadow pass, depth only. see: src/render/scene_renderer.cpp
layout(location = 0) in vec3 aPosWs;

uniform mat4 uShadowClipFromWorld;

void main() { gl_Position = uShadowClipFromWorld * vec4(aPosWs, 1.0f); }
