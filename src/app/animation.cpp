#include "app/animation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>

#include "base/input_error.h"
#include "kernel/methods.h"
#include "kernel/trace_explain.h"
#include "measure/failure_measures.h"
#include "measure/stability.h"
#include "scene/light.h"

namespace pcf {

namespace {

// The ends of the sweeps: the elevations and constant biases of `stability`'s acne and leak
// sweeps (measure/stability.h, StabilityOptions), map sizes from coarse to fine.
constexpr double SUN_FROM_DEG = 90.0, SUN_TO_DEG = 2.0;
constexpr double BIAS_FROM = 0.0005, BIAS_TO = 0.064;
constexpr double MAP_FROM = 32.0, MAP_TO = 2048.0;
// The turn: an eighth of a turn, the stability cascades sweep's (measure/stability_cascades.h).
constexpr double TURN_FROM_DEG = 0.0, TURN_TO_DEG = 45.0;

// t in [0,1] across the frames.
double progress(int k, int frames) {
    return frames > 1 ? static_cast<double>(k) / static_cast<double>(frames - 1) : 0.0;
}

double logLerp(double a, double b, double t) { return a * std::pow(b / a, t); }

std::string methodLabel(int method, int kernel) {
    std::string name(methodInfo(method).name);
    return methodInfo(method).usesKernel ? name + " " + std::to_string(kernel) : name;
}

}  // namespace

double animationSweepValue(const AnimationOptions& o, int k) {
    double t = progress(k, o.frames);
    switch (o.sweep) {
        case AnimationSweep::Light:
            return static_cast<double>(k % SHIMMER_STEPS) / SHIMMER_STEPS;
        case AnimationSweep::Camera:
            return static_cast<double>(k) / StabilityOptions{}.cameraFrames;
        case AnimationSweep::Sun: {
            double from = o.from.value_or(SUN_FROM_DEG), to = o.to.value_or(SUN_TO_DEG);
            return from + (to - from) * t;
        }
        case AnimationSweep::Bias:
            return logLerp(o.from.value_or(BIAS_FROM), o.to.value_or(BIAS_TO), t);
        case AnimationSweep::MapSize:
            return std::round(logLerp(o.from.value_or(MAP_FROM), o.to.value_or(MAP_TO), t));
        case AnimationSweep::Turn: {
            double from = o.from.value_or(TURN_FROM_DEG), to = o.to.value_or(TURN_TO_DEG);
            return from + (to - from) * t;
        }
    }
    return 0.0;
}

namespace {

std::string numberWords(double v, int decimals) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

}  // namespace

std::string animationSweepWords(const AnimationOptions& o, int k) {
    double now = animationSweepValue(o, k);
    double first = animationSweepValue(o, 0), last = animationSweepValue(o, o.frames - 1);
    std::string frame = "Frame " + std::to_string(k + 1) + " of " + std::to_string(o.frames) + ". ";
    switch (o.sweep) {
        case AnimationSweep::Light:
            return frame + "The shadow map's texel grid creeps under the still world by 1/" +
                   std::to_string(SHIMMER_STEPS) + " texel a frame, starting over after a whole " +
                   "texel" + (o.snap ? ", and the map's fit is snapped back to whole texels" : "") +
                   "; now it is " + formatNumber(static_cast<float>(now)) + " texel along.";
        case AnimationSweep::Camera:
            return frame + "The camera slides right and up by 1/6 pixel a frame; now it is " +
                   numberWords(now, 2) + " pixels along.";
        case AnimationSweep::Sun:
            return frame + "The sun " + (last >= first ? "rises" : "sinks") + " from " +
                   numberWords(first, 0) + " to " + numberWords(last, 0) +
                   " degrees above the horizon; now it stands " + numberWords(now, 1) +
                   " degrees high.";
        case AnimationSweep::Bias:
            return frame + "The constant bias " + (last >= first ? "grows" : "shrinks") + " from " +
                   formatNumber(static_cast<float>(first)) + " to " +
                   formatNumber(static_cast<float>(last)) + "; now it is " +
                   formatNumber(static_cast<float>(now)) + ".";
        case AnimationSweep::MapSize:
            return frame + "The shadow map " + (last >= first ? "grows" : "shrinks") + " from " +
                   numberWords(first, 0) + " to " + numberWords(last, 0) +
                   " texels a side; now it has " + numberWords(now, 0) + ".";
        case AnimationSweep::Turn:
            return frame + "The camera turns about the ringed point from " + numberWords(first, 0) +
                   " to " + numberWords(last, 0) +
                   " degrees while the sun stands still; now it has turned " + numberWords(now, 1) +
                   " degrees.";
    }
    return frame;
}

bool isStepsOwnAnimation(const LessonStep& step, const AnimationOptions& o) {
    if (!step.animate) return false;
    AnimationOptions own = stepAnimationOptions(step);
    return own.sweep == o.sweep && own.frames == o.frames && own.snap == o.snap &&
           animationSweepValue(own, 0) == animationSweepValue(o, 0) &&
           animationSweepValue(own, own.frames - 1) == animationSweepValue(o, o.frames - 1);
}

int defaultCompareMethod(int stepMethod) {
    return methodInfo(stepMethod).hard ? PCF_GATHER : PCF_NEAREST;
}

AnimationOptions stepAnimationOptions(const LessonStep& step) {
    const StepAnimation& a = *step.animate;
    AnimationOptions o;
    o.sweep = a.sweep;
    o.frames = a.frames;
    o.snap = a.snap;
    o.from = a.from;
    o.to = a.to;
    o.compareMethod = defaultCompareMethod(step.settings.method);
    return o;
}

Animation::Animation(Session& session, const AnimationOptions& options)
    : mSession(session),
      mOptions(options),
      mBase(session.settings()),
      mScene(session.scene()),
      mPivot(session.point()) {
    const Lesson& lesson = session.lesson();
    int step = session.step();
    if (step >= 0 && step < session.stepCount()) {
        mStepsOwn = isStepsOwnAnimation(lesson.steps[static_cast<size_t>(step)], options);
    }
}

Animation::Animation(Session& session, const AnimationOptions& options, CompareView& compare)
    : Animation(session, options) {
    mSplit = &compare;
    mOptions.compareMethod = -1;  // the parts are the comparison
    mParts.resize(static_cast<size_t>(compare.parts()));
    compare.setTraceBand(mOptions.flicker);
}

// A split view's frame: the parts take the swept state, are traced, and their visibilities join
// their curves before the trace is drawn.
void Animation::composeCompare() {
    mSplit->follow(mSession);
    bool recorded = false;
    auto record = [this, &recorded] {
        if (recorded) return;
        recorded = true;
        for (int i = 0; i < mSplit->parts(); ++i) {
            std::optional<float> v = mSplit->visibility(i);
            mParts[static_cast<size_t>(i)].push_back(v ? *v : -1.0f);
        }
        mCurve = mParts[0];
        mCompare = mParts[1];
    };
    if (mOptions.flicker) {
        mSplit->setFlickerTrace([this, record] {
            record();
            return flickerTrace();
        });
    }
    mSplit->compose();
    mSplit->setFlickerTrace({});
    record();
}

void Animation::apply(int k) {
    double v = animationSweepValue(mOptions, k);
    LessonSettings s = mBase;
    switch (mOptions.sweep) {
        case AnimationSweep::Light:
            mSession.setShadowFit(shimmerShadowFit(shadowClipFromWorld(mScene), s.mapSize,
                                                   k % SHIMMER_STEPS, mOptions.snap));
            break;
        case AnimationSweep::Camera:
            mSession.setCamera(cameraSlidByPixels(
                mScene.camera, static_cast<int>(mSession.layout().scene.h), static_cast<float>(v)));
            break;
        case AnimationSweep::Sun: {
            Light light = mScene.light;
            light.directionWs = directionAtElevation(light.directionWs, static_cast<float>(v));
            mSession.setLight(light);
            break;
        }
        case AnimationSweep::Bias:
            if (s.bias == BiasMode::None) s.bias = BiasMode::Constant;
            s.constantBias = static_cast<float>(v);
            break;
        case AnimationSweep::MapSize:
            s.mapSize = static_cast<int>(v);
            break;
        case AnimationSweep::Turn:
            turnCamera(static_cast<float>(v));
            break;
    }
    mSession.setSettings(s);
    mSession.setMotion(FrameMotion{animationSweepWords(mOptions, k), mBase, mStepsOwn,
                                   std::string(animationSweepName(mOptions.sweep)), k + 1,
                                   mOptions.frames, v});
}

// The camera turned by `degrees` about the vertical line through the pinned point (else the
// view's target): eye and target move round it together, so the point keeps its place in the
// camera's view (its pixel and view depth) while the view direction turns under the light. The
// point stays pinned, as the lesson pins it.
void Animation::turnCamera(float degrees) {
    glm::vec3 pivot = mPivot ? mPivot->posWs : mScene.camera.targetWs;
    glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0, 1, 0));
    auto turned = [&](glm::vec3 p) { return pivot + glm::vec3(turn * glm::vec4(p - pivot, 0.0f)); };
    Camera camera = mScene.camera;
    camera.eyeWs = turned(camera.eyeWs);
    camera.targetWs = turned(camera.targetWs);
    mSession.setCamera(camera);
    if (mPivot) mSession.pinPoint(*mPivot);
}

void Animation::restore() {
    mSession.setFlickerTrace({});
    mSession.setMotion(std::nullopt);
    mSession.setShadowFit(std::nullopt);
    // Only what the sweep moved: setting the camera again would re-pin the point under its pixel.
    if (mOptions.sweep == AnimationSweep::Sun) mSession.setLight(mScene.light);
    if (mOptions.sweep == AnimationSweep::Camera) mSession.setCamera(mScene.camera);
    if (mOptions.sweep == AnimationSweep::Turn) {
        mSession.setCamera(mScene.camera);
        if (mPivot) mSession.pinPoint(*mPivot);
    }
    mSession.setSettings(mBase);
}

void Animation::showFrame(int k) {
    apply(k);
    // The curve up to this frame: a frame shown again (stepping back) replaces what it recorded.
    mCurve.resize(std::min(mCurve.size(), static_cast<size_t>(k)));
    mCompare.resize(std::min(mCompare.size(), static_cast<size_t>(k)));
    auto recorded = std::make_shared<bool>(false);
    mSession.setFlickerTrace([this, recorded] {
        if (!*recorded) {
            *recorded = true;
            record();
        }
        return flickerTrace();
    });
}

void Animation::record() {
    const std::optional<Trace>& trace = mSession.trace();
    mCurve.push_back(trace ? trace->visibility : -1.0f);
    if (mOptions.compareMethod >= 0) {
        std::optional<float> v =
            mSession.visibilityWith(mOptions.compareMethod, mOptions.compareKernel);
        mCompare.push_back(v ? *v : -1.0f);
    }
}

void Animation::composeFrame(int k) {
    apply(k);
    if (mSplit) return composeCompare();
    bool recorded = false;
    // Called by compose() once the frame's lookup is traced: the point's value joins the curve
    // before the trace is drawn.
    auto once = [this, &recorded] {
        if (recorded) return;
        recorded = true;
        record();
    };
    if (mOptions.flicker) {
        mSession.setFlickerTrace([this, once] {
            once();
            return flickerTrace();
        });
        mSession.compose();
        mSession.setFlickerTrace({});
    } else {
        mSession.compose();
    }
    once();  // a chart step draws no trace; the curve still grows
}

FlickerTrace Animation::flickerTrace() const {
    FlickerTrace t;
    char title[96];
    std::snprintf(title, sizeof title, "visibility at the ring   %s %.4g %s",
                  std::string(animationSweepName(mOptions.sweep)).c_str(),
                  animationSweepValue(mOptions, static_cast<int>(mCurve.size()) - 1),
                  std::string(animationSweepUnit(mOptions.sweep)).c_str());
    t.title = title;
    t.frameCount = mOptions.frames;
    auto curve = [](const std::vector<float>& values, const std::string& name, Colour colour) {
        FlickerCurve c;
        for (float v : values) c.values.push_back(std::max(v, 0.0f));
        char label[96];
        std::snprintf(label, sizeof label, "%-12s mean |dv| %.3f", name.c_str(),
                      curveFlicker(c.values));
        c.label = label;
        c.colour = colour;
        return c;
    };
    if (mSplit) {
        for (int i = 0; i < mSplit->parts(); ++i) {
            t.curves.push_back(curve(mParts[static_cast<size_t>(i)],
                                     comparePartLabel(mSplit->spec(), i), comparePartColour(i)));
        }
        return t;
    }
    const LessonSettings& s = mSession.settings();
    t.curves.push_back(curve(mCurve, methodLabel(s.method, s.kernel), FLICKER_MAIN_COLOUR));
    if (mOptions.compareMethod >= 0) {
        t.curves.push_back(curve(mCompare,
                                 methodLabel(mOptions.compareMethod, mOptions.compareKernel),
                                 FLICKER_COMPARE_COLOUR));
    }
    return t;
}

FlickerCurves stepFlickerCurves(const Lesson& lesson, int step, const LessonSettings& s,
                                glm::ivec2 size) {
    Session session(size, false);
    session.setLesson(lesson);
    session.goToStep(step);
    const LessonStep& st = session.lesson().steps[static_cast<size_t>(step)];
    if (!st.animate) return {};
    session.setSettings(s);
    session.setSceneOnly(true);
    AnimationOptions o = stepAnimationOptions(st);
    o.flicker = false;  // the curves, not their picture
    Animation animation(session, o);
    for (int k = 0; k < o.frames; ++k) animation.composeFrame(k);
    return {animation.curve(), animation.compareCurve()};
}

}  // namespace pcf
