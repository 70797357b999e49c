// inspector_keys.cpp: the viewer's keys as the help overlay (H) and `pcfscope view --help` list
// them, and the overlay drawn from that list.
#include "overlay/inspector_plan.h"

namespace pcf {

const std::vector<std::pair<std::string, std::string>>& viewerKeys() {
    static const std::vector<std::pair<std::string, std::string>> keys = {
        {"click", "pin the scene point under the cursor"},
        {"Up / Down", "pin the point one pixel row up / down"},
        {"Shift+arrows", "pin the point one pixel over"},
        {"Space, Right", "next page of the text, then next step"},
        {"Left, Backspace", "previous step"},
        {"Home / End", "first / last step"},
        {"M / Shift+M", "next / previous method"},
        {"[ / ]", "smaller / larger kernel"},
        {"- / +", "smaller / larger shadow map"},
        {"B / Shift+B", "next / previous bias mode"},
        {"Q", "texture unit: exact / hw8"},
        {"G", "texel grid on the scene on / off"},
        {"A", "aliasing heat map (pixels per texel)"},
        {"O / Shift+O, S", "slide the map's grid 1/8 texel; snap"},
        {"C", "split view: the step's compare, or this method and nearest"},
        {"Z", "magnifier: a close-up on the point, a texel many pixels wide"},
        {"L / Shift+L", "next / previous lesson"},
        {"E", "export this frame (PNG + JSON)"},
        {"P", "presentation mode"},
        {"H", "this help"},
        {"F", "fullscreen"},
        {"Esc", "quit"},
    };
    return keys;
}

namespace inspector_detail {

void planHelp(Planner& pl, const InspectorLayout& l, const TypeSizes& t) {
    float fs = t.body;
    const auto& keys = viewerKeys();
    float keyW = 0.0f, whatW = 0.0f;
    for (const auto& [key, what] : keys) {
        keyW = std::max(keyW, measureText(FontFace::Mono, fs, key).x);
        whatW = std::max(whatW, measureText(FontFace::Sans, fs, what).x);
    }
    float lh = lineHeightOf(fs);
    float w = std::min(static_cast<float>(l.frameSize.x) - 8.0f, keyW + whatW + fs * 4.0f);
    float h = std::min(static_cast<float>(l.frameSize.y) - 8.0f,
                       (static_cast<float>(keys.size()) + 2.5f) * lh + fs);
    Rect box{std::round((l.frameSize.x - w) * 0.5f), std::round((l.frameSize.y - h) * 0.5f), w, h};
    pl.fill(box, Colour{0.02f, 0.03f, 0.05f, 0.94f});
    pl.op([=](Canvas& c) { c.strokeRect(box, 2.0f, ACCENT); });
    float y = box.y + fs * 0.6f;
    pl.op([=](Canvas& c) { c.text({box.x + fs, y}, "Keys", {FontFace::Sans, fs, ACCENT}); });
    y += lh * 1.4f;
    for (const auto& [key, what] : keys) {
        if (y + lh > box.bottom()) break;
        std::string k = key, wt = what;
        float yy = y;
        pl.op([=](Canvas& c) {
            c.text({box.x + fs, yy}, k, {FontFace::Mono, fs, TEXT});
            c.text({box.x + fs * 2.0f + keyW, yy}, wt, {FontFace::Sans, fs, TEXT_DIM});
        });
        y += lh;
    }
}

}  // namespace inspector_detail

}  // namespace pcf
