// viewer_split.h: the viewer's split view (key C, compare_view.h) and magnifier (key Z,
// magnifier.h), kept apart from viewer.cpp's key table. The split view compares what the step's
// `compare` names, else the live method against nearest (pcf-gather 3 against a nearest step),
// as `animate --compare auto` does; it follows every key and click on the main view.
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "app/compare_view.h"
#include "app/session.h"
#include "scene/camera.h"

namespace pcf {

class ViewerSplit {
  public:
    // C toggles the split view, Z the magnifier: returns whether `key` (a GLFW key) was one.
    bool press(Session& session, int key);
    // After any other key or click: the magnifier stays on the (maybe new) point; a new lesson
    // (a new camera) turns it off.
    void follow(Session& session);
    bool splitOn() const { return mSplit != nullptr; }
    bool magnified() const { return mMagnified; }
    // The frame into `fbo` (0: the window) at `size`: the split view when on, else the session's.
    void composeInto(Session& session, unsigned fbo, glm::ivec2 size);
    // The frame composed offscreen and read back (screenshots), RGBA8 rows top-down: as it is
    // written, without the window's key hints (Session::interactive).
    std::vector<uint8_t> readFrame(Session& session);

  private:
    void toggleSplit(Session& session);
    void toggleMagnifier(Session& session);
    // The split view up to date with the session at `size`, or nullptr (off, or refused).
    CompareView* readySplit(Session& session, glm::ivec2 size);

    std::unique_ptr<CompareView> mSplit;
    bool mMagnified = false;
    Camera mWide;             // the view the magnifier magnifies
    std::string mWideLesson;  // the lesson it belongs to
    int mStep = 0;            // the step whose point it magnifies
};

// The split view C shows: the step's `compare`, else the method on screen against nearest.
CompareSpec viewerCompareSpec(const Session& session);

}  // namespace pcf
