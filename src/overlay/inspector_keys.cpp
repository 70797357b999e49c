// inspector_keys.cpp: the viewer's keys as the help overlay (H) and `pcfscope view --help` list
// them, and the overlay drawn from that list.
#include "kernel/settings.h"
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
        {"R", "a question: reveal / hide the answer"},
        {"0-9 . / -, Enter", "a question: type an answer, Enter judges and reveals it"},
        {"N", "exercise mode: questions from this lesson, answers scored"},
        {"Space (animation)", "an animation step: play / pause"},
        {". / ,", "an animation step: next / previous frame"},
        {"M / Shift+M", "next / previous method"},
        {"[ / ]", "smaller / larger kernel"},
        {"- / +", "smaller / larger shadow map"},
        {"B / Shift+B", "next / previous bias mode"},
        {"Q", "texture unit: exact / hw8"},
        {"G", "texel grid on the scene on / off"},
        {"A", "aliasing heat map (pixels per texel)"},
        {"O / Shift+O, S", "slide the map's grid 1/8 texel; snap"},
        {"V / Shift+V", "bias amount up / down (1, 2, 5 a decade)"},
        {"U / Shift+U", "the sun 5 degrees higher / lower"},
        {"T / Shift+T", "turn the sun 15 degrees one way / the other"},
        {"W / Shift+W", "next / previous kernel weights"},
        {"I / Shift+I", "gaussian weights' sigma larger / smaller"},
        {"K", "cull mode of the shadow pass"},
        {"D", "depth format: " + depthFormatNames()},
        {"N", "shading: lit / the visibility alone (no N.L)"},
        {"J", "shading: tinted by the cascade each pixel reads / lit"},
        {"Y", "cascades frozen: the camera backs away, their boxes and splits drawn"},
        {"X", "marks on the scene on / off"},
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
    auto measure = [&] {
        keyW = whatW = 0.0f;
        for (const auto& [key, what] : keys) {
            keyW = std::max(keyW, measureText(FontFace::Mono, fs, key).x);
            whatW = std::max(whatW, measureText(FontFace::Sans, fs, what).x);
        }
    };
    measure();
    float lh = lineHeightOf(fs);
    // One column when the list fits the frame's height, else two side by side, the type made
    // smaller when two do not fit the frame's width.
    float room = static_cast<float>(l.frameSize.y) - 8.0f - fs - 2.5f * lh;
    int n = static_cast<int>(keys.size());
    int columns = n * lh <= room ? 1 : 2;
    int rows = (n + columns - 1) / columns;
    float columnW = keyW + whatW + fs * 3.0f;
    float across = static_cast<float>(l.frameSize.x) - 8.0f;
    if (columnW * columns + fs > across) {
        fs = std::floor(fs * across / (columnW * columns + fs));
        measure();
        lh = lineHeightOf(fs);
        columnW = keyW + whatW + fs * 3.0f;
    }
    float w = std::min(static_cast<float>(l.frameSize.x) - 8.0f, columnW * columns + fs);
    float h = std::min(static_cast<float>(l.frameSize.y) - 8.0f,
                       (static_cast<float>(rows) + 2.5f) * lh + fs);
    Rect box{std::round((l.frameSize.x - w) * 0.5f), std::round((l.frameSize.y - h) * 0.5f), w, h};
    pl.box(BoxKind::Panel, box, "help", "help");
    pl.fill(box, Colour{0.02f, 0.03f, 0.05f, 0.94f});
    pl.op([=](Canvas& c) { c.strokeRect(box, 2.0f, ACCENT); });
    float top = box.y + fs * 0.6f;
    pl.op([=](Canvas& c) { c.text({box.x + fs, top}, "Keys", {FontFace::Sans, fs, ACCENT}); });
    top += lh * 1.4f;
    for (int k = 0; k < n; ++k) {
        float x = box.x + fs + static_cast<float>(k / rows) * columnW;
        float y = top + static_cast<float>(k % rows) * lh;
        if (y + lh > box.bottom()) continue;
        std::string key = keys[static_cast<size_t>(k)].first;
        std::string what = keys[static_cast<size_t>(k)].second;
        pl.op([=](Canvas& c) {
            c.text({x, y}, key, {FontFace::Mono, fs, TEXT});
            c.text({x + fs + keyW, y}, what, {FontFace::Sans, fs, TEXT_DIM});
        });
    }
}

}  // namespace inspector_detail

}  // namespace pcf
