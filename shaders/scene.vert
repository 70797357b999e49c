// scene.vert: the camera pass. Passes world position and normal on; the fragment shader does
// the light-space projection itself so that the (u, v, ref) it writes out are exactly the values
// it filtered with. see: scene.frag, src/render/scene_renderer.cpp
layout(location = 0) in vec3 aPosWs;
layout(location = 1) in vec3 aNormalWs;

uniform mat4 uClipFromWorld;

out vec3 vPosWs;
out vec3 vNormalWs;

void main() {
    vPosWs = aPosWs;
    vNormalWs = aNormalWs;
    gl_Position = uClipFromWorld * vec4(aPosWs, 1.0f);
}
