// compare_view.h: the split view (issue 20, "side by side"): two or three settings of the same
// step on the same pinned point, each part its own scene (a half or a third of the frame, the
// same camera, light and point), a compact inspector under it (its setting, the point's
// visibility and lookup) and the difference of its visibility from the first part's. The viewer
// (key C), `export --compare` and `animate --compare` compose it; every part is an ordinary
// scene-only Session, so a part shows exactly what that setting alone shows.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/session.h"
#include "draw/canvas.h"
#include "lesson/compare_spec.h"
#include "overlay/flicker_trace.h"
#include "render/gl_objects.h"

namespace pcf {

// The parts' colours: their labels and their flicker-trace curves.
constexpr Colour COMPARE_THIRD_COLOUR{0.78f, 0.58f, 0.98f, 1.0f};
Colour comparePartColour(int part);

// The smallest part's scene a split view lays out.
constexpr int MIN_COMPARE_PART_WIDTH = 160;
constexpr int MIN_COMPARE_PART_HEIGHT = 90;
// Why a frame is too small for a split view of `parts` (with a flicker trace's band when
// traceBand), or nullopt: the commands check it before anything is made.
std::optional<std::string> compareFrameProblem(glm::ivec2 frame, int parts, bool presentation,
                                               bool traceBand);

class CompareView {
  public:
    // Needs a current OpenGL 4.5 context. Throws UsageError when the frame is too narrow for the
    // spec's parts.
    CompareView(glm::ivec2 frameSize, bool presentation, CompareSpec spec);

    const CompareSpec& spec() const { return mSpec; }
    int parts() const { return static_cast<int>(mParts.size()); }
    glm::ivec2 frameSize() const { return mFrameSize; }
    void setFrameSize(glm::ivec2 frameSize);
    // Where part i's scene is drawn in the frame (top-left origin), and the size each part's
    // scene is rendered at (all the same).
    Rect partRect(int part) const;
    glm::ivec2 partSceneSize() const;

    // Takes the main view's state: its lesson, step, light, camera, shadow fit and pinned
    // point, its settings with each part's values set (compare_spec.h: comparePart, whose
    // std::invalid_argument passes through when the live settings cannot take them), its status
    // line, its help (H) and whether it is the window's (Session::interactive).
    void follow(const Session& main);

    void compose();
    void composeInto(GLuint framebuffer);  // 0: the window's back buffer
    GLuint frameFramebuffer() const { return mFrame.framebuffer.id(); }
    std::vector<uint8_t> readFrame() const;  // RGBA8, rows top-down

    const Session& part(int i) const { return *mParts[static_cast<size_t>(i)]; }
    // Part i's visibility at the point in the last compose; nullopt off a receiver.
    std::optional<float> visibility(int part) const;
    // What part i's inspector says (i >= 1): visibility(i) - visibility(0), as drawn.
    std::optional<float> difference(int part) const;

    // A flicker trace drawn across the frame under the parts (animations): the source is
    // called after every part is traced, so it can take this frame's visibilities.
    void setFlickerTrace(std::function<FlickerTrace()> source) { mFlicker = std::move(source); }
    // Keeps a band under the panels for that trace (the parts' scenes are shorter by it).
    void setTraceBand(bool on);
    // The frame as JSON: the spec, each part's label, settings, visibility and difference, the
    // status line, the layout's boxes and, on an animation's frame, its "motion" (session.h).
    std::string json() const;
    // The status line's words (the main view's, then what is compared) and the boxes of the last
    // compose: the status line, its keys hint and, with the main view's help on (H), the key list
    // over the frame, as the lesson's frame draws them (inspector.h: planStatusFrame).
    const std::string& status() const { return mStatus; }
    const std::vector<LayoutBox>& boxes() const { return mBoxes; }

  private:
    float textPx() const;
    float panelHeight() const;
    void drawPanels();
    void drawTraceBand();

    CompareSpec mSpec;
    bool mPresentation = false;
    bool mTraceBand = false;
    glm::ivec2 mFrameSize{0, 0};
    std::vector<std::unique_ptr<Session>> mParts;
    std::function<FlickerTrace()> mFlicker;
    std::string mStatus;
    bool mHelp = false;
    bool mInteractive = false;  // the window's: its keys hint (follow takes it from the main view)
    std::optional<FrameMotion> mMotion;  // the main view's animation frame, for the JSON
    std::vector<LayoutBox> mBoxes;
    Canvas mCanvas;
    OffscreenTarget mFrame;
};

}  // namespace pcf
