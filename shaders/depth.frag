// depth.frag: the shadow pass writes depth only; the rasterizer does it all.
void main() {}
