#include "app/viewer_split.h"

#include <epoxy/gl.h>
// After epoxy, without GLFW pulling in its own GL header.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <stdexcept>

#include "app/animation.h"
#include "app/magnifier.h"
#include "kernel/methods.h"

namespace pcf {

CompareSpec viewerCompareSpec(const Session& session) {
    const Lesson& lesson = session.lesson();
    if (!lesson.steps.empty()) {
        const CompareSpec& own = lesson.steps[static_cast<size_t>(session.step())].compare;
        if (!own.empty()) return own;
    }
    int method = session.settings().method;
    int other = defaultCompareMethod(method);
    CompareSpec spec;
    addCompareKey(spec, "method",
                  {std::string(methodInfo(method).name), std::string(methodInfo(other).name)});
    return spec;
}

bool ViewerSplit::press(Session& session, int key) {
    if (key == GLFW_KEY_C) {
        toggleSplit(session);
        return true;
    }
    if (key == GLFW_KEY_Z) {
        toggleMagnifier(session);
        return true;
    }
    return false;
}

void ViewerSplit::toggleSplit(Session& session) {
    if (mSplit) {
        mSplit.reset();
        return;
    }
    try {
        mSplit = std::make_unique<CompareView>(session.frameSize(), session.presentation(),
                                               viewerCompareSpec(session));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "view: no split view: %s\n", e.what());
    }
}

void ViewerSplit::toggleMagnifier(Session& session) {
    mMagnified = !mMagnified;
    if (mMagnified) {
        mWide = session.scene().camera;
        mWideLesson = session.lesson().sourcePath;
        mStep = session.step();
        magnifySession(session, mWide);
        return;
    }
    std::optional<ScenePoint> point = session.point();
    session.setCamera(mWide);
    if (point) session.pinPoint(*point);
}

void ViewerSplit::follow(Session& session) {
    if (!mMagnified) return;
    if (session.lesson().sourcePath != mWideLesson) {
        mMagnified = false;  // a new lesson came with its own camera
        return;
    }
    if (session.step() != mStep) {
        // A new step's point is found as the lesson finds it, in the lesson's own view (the
        // close-up may not see it), then magnified.
        mStep = session.step();
        session.setCamera(mWide);
        session.goToStep(mStep);
    }
    magnifySession(session, mWide);
}

CompareView* ViewerSplit::readySplit(Session& session, glm::ivec2 size) {
    if (!mSplit) return nullptr;
    try {
        // A step with its own `compare` is shown as it says; the spec follows the step.
        CompareSpec spec = viewerCompareSpec(session);
        if (!(spec == mSplit->spec())) {
            mSplit = std::make_unique<CompareView>(size, session.presentation(), spec);
        }
        mSplit->setFrameSize(size);
        mSplit->follow(session);
        return mSplit.get();
    } catch (const std::exception& e) {
        // The live settings cannot take the split (a bias mode the method refuses, a window
        // too narrow): said once, and the lesson's frame instead.
        std::fprintf(stderr, "view: split view off: %s\n", e.what());
        mSplit.reset();
        return nullptr;
    }
}

void ViewerSplit::composeInto(Session& session, unsigned fbo, glm::ivec2 size) {
    session.setFrameSize(size);
    if (CompareView* split = readySplit(session, size)) return split->composeInto(fbo);
    session.composeInto(fbo);
}

std::vector<uint8_t> ViewerSplit::readFrame(Session& session) {
    // A written frame, as `export` writes it: no hint of the window's keys.
    bool interactive = session.interactive();
    session.setInteractive(false);
    std::vector<uint8_t> rgba;
    if (CompareView* split = readySplit(session, session.frameSize())) {
        split->compose();
        rgba = split->readFrame();
    } else {
        session.compose();
        rgba = session.readFrame();
    }
    session.setInteractive(interactive);
    return rgba;
}

}  // namespace pcf
