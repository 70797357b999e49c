#include "app/session.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "analysis/bench_report.h"
#include "analysis/speed_chart.h"
#include "analysis/stability_chart.h"
#include "analysis/stability_report.h"
#include "app/cli_util.h"
#include "kernel/methods.h"
#include "kernel/trace_explain.h"
#include "kernel/trace_json.h"
#include "lesson/lesson_text.h"
#include "scene/input_error.h"
#include "scene/input_file.h"

namespace pcf {

namespace {

// "pcf-gather N=3   bias constant 0.02   cull back   map 256 32f": the state, in the status line's
// words.
std::string settingsSummary(const LessonSettings& s) {
    const MethodInfo& info = methodInfo(s.method);
    // A stream: GCC 12 warns falsely (-Wrestrict) on chains of string operator+.
    std::ostringstream line;
    line << info.name;
    if (info.usesKernel) line << " N=" << s.kernel;
    if (s.weights != PCF_WEIGHTS_BOX) line << " " << weightsName(s.weights);
    if (info.usesRadius) line << " R=" << formatNumber(s.radius) << (s.rotate ? " rotated" : "");
    line << "   bias " << s.bias;
    if (s.bias != "none") line << " " << formatNumber(s.constantBias);
    if (s.bias == "slope") {
        line << " +" << formatNumber(s.slopeBias) << "tan<=" << formatNumber(s.slopeMax);
    }
    if (s.bias == "normal") line << " k=" << formatNumber(s.normalOffset);
    if (s.bias == "soft") line << " x" << formatNumber(s.softScale);
    line << "   cull " << s.cull << "   map " << s.mapSize << " " << s.depthFormat;
    if (s.precision == PCF_PRECISION_HW8) line << "   hw8";
    return line.str();
}

std::string statusLine(const LessonSettings& s, glm::ivec2 sceneSize, double frameTimeMs) {
    std::ostringstream line;
    line << settingsSummary(s) << "   scene " << sceneSize.x << "x" << sceneSize.y;
    if (frameTimeMs >= 0.0) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "   %.1f ms", frameTimeMs);
        line << buf;
    }
    return line.str();
}

}  // namespace

std::vector<std::string> builtInLessons() {
    std::vector<std::string> paths;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(PCFSCOPE_LESSON_DIR, ec)) {
        if (entry.path().extension() == ".toml") paths.push_back(entry.path().string());
    }
    std::sort(paths.begin(), paths.end());
    return paths;
}

std::string resolveLesson(const std::string& nameOrPath) {
    std::error_code ec;
    if (nameOrPath.find('/') != std::string::npos || nameOrPath.ends_with(".toml")) {
        return nameOrPath;  // a path: parseLessonFile says what is wrong with it
    }
    std::vector<std::string> lessons = builtInLessons();
    std::string names;
    for (size_t k = 0; k < lessons.size(); ++k) {
        std::string stem = std::filesystem::path(lessons[k]).stem().string();
        if (stem == nameOrPath || std::to_string(k + 1) == nameOrPath) return lessons[k];
        names += (names.empty() ? "" : ", ") + stem;
    }
    throw UsageError("unknown lesson '" + nameOrPath + "' (a .toml path, a number 1.." +
                     std::to_string(lessons.size()) + ", or one of: " + names + ")");
}

namespace {

// A name the lesson parser or the viewer's keys already checked: an unknown one here is a bug,
// reported as such instead of silently drawing something else.
template <class T>
T checked(std::optional<T> value, const char* what, const std::string& name) {
    if (!value) throw std::logic_error("unchecked " + std::string(what) + " '" + name + "'");
    return *value;
}

}  // namespace

RenderSettings renderSettingsFor(const LessonSettings& s, glm::ivec2 sceneSize) {
    RenderSettings r;
    r.method = s.method;
    r.kernel = s.kernel;
    r.radius = s.radius;
    r.rotatePerPixel = s.rotate;
    r.weights = s.weights;
    r.sigma = s.sigma;
    r.precision = s.precision;
    r.mapSize = s.mapSize;
    r.depthFormat = checked(depthFormatFromName(s.depthFormat), "depth format", s.depthFormat);
    r.bias = checked(biasModeFromName(s.bias), "bias", s.bias);
    r.constantBias = s.constantBias;
    r.slopeBias = s.slopeBias;
    r.slopeMax = s.slopeMax;
    r.normalOffset = s.normalOffset;
    r.softScale = s.softScale;
    r.shadowCull = checked(cullModeFromName(s.cull), "cull", s.cull);
    r.frameSize = sceneSize;
    return r;
}

Session::Session(glm::ivec2 frameSize, bool presentation) : mPresentation(presentation) {
    setFrameSize(frameSize);
}

namespace {

// A chart's CSV, read with the checks every input file gets (scene/input_file.h).
std::string readChartText(const std::string& csvPath) { return readInputFile(csvPath); }

// Refuses a chart of more rows than one frame can show.
template <class Row>
std::vector<Row> limitChartRows(std::vector<Row> rows, const std::string& csvPath) {
    if (rows.size() > MAX_CHART_ROWS) {
        throw InputError(csvPath, 0,
                         std::to_string(rows.size()) + " rows; a chart shows at most " +
                             std::to_string(MAX_CHART_ROWS));
    }
    return rows;
}

std::vector<BenchRow> readChartRows(const std::string& csvPath) {
    return limitChartRows(parseBenchCsv(readChartText(csvPath), csvPath), csvPath);
}

std::vector<StabilityRow> readStabilityRows(const std::string& csvPath) {
    return limitChartRows(parseStabilityCsv(readChartText(csvPath), csvPath), csvPath);
}

// A step's chart: "PATH" (a bench.csv) or "PATH#VIEW" (a stability.csv and which of its charts:
// acne, leak or shimmer).
struct ChartRef {
    std::string path;
    std::string view;  // empty for a bench chart
};

ChartRef chartRef(const std::string& chart) {
    size_t hash = chart.rfind('#');
    if (hash == std::string::npos) return {chart, ""};
    return {chart.substr(0, hash), chart.substr(hash + 1)};
}

// The stability chart `view` of a stability.csv, or InputError for an unknown view or no rows.
std::vector<uint8_t> drawStabilityView(const ChartRef& ref, glm::ivec2 size) {
    std::vector<StabilityRow> rows = readStabilityRows(ref.path);
    std::string subtitle =
        "measured by pcfscope stability, " + std::filesystem::path(ref.path).filename().string();
    std::vector<uint8_t> rgba;
    if (ref.view == "acne") {
        rgba = drawAcneChart(rows, size, subtitle);
    } else if (ref.view == "leak") {
        rgba = drawLeakChart(rows, size, subtitle);
    } else if (ref.view == "shimmer") {
        rgba = drawShimmerChart(rows, size, subtitle);
    } else {
        throw InputError(ref.path, 0,
                         "unknown stability chart '#" + ref.view +
                             "' (known: #acne, #leak, #shimmer)");
    }
    if (rgba.empty()) throw InputError(ref.path, 0, "no " + ref.view + " rows to chart");
    return rgba;
}

// Throws InputError unless the stability.csv has rows for the view.
void checkStabilityView(const ChartRef& ref) {
    std::vector<StabilityRow> rows = readStabilityRows(ref.path);
    if (ref.view != "acne" && ref.view != "leak" && ref.view != "shimmer") {
        throw InputError(ref.path, 0,
                         "unknown stability chart '#" + ref.view +
                             "' (known: #acne, #leak, #shimmer)");
    }
    for (const StabilityRow& r : rows) {
        if (r.sweep == ref.view) return;
    }
    throw InputError(ref.path, 0, "no " + ref.view + " rows to chart");
}

}  // namespace

Lesson loadLessonChecked(const std::string& path) {
    Lesson lesson = parseLessonFile(path);
    if (lesson.steps.empty()) throw UsageError(path + ": the lesson has no steps");
    for (size_t i = 0; i < lesson.steps.size(); ++i) {
        const LessonStep& step = lesson.steps[i];
        if (step.chart.empty()) continue;
        try {
            ChartRef ref = chartRef(step.chart);
            if (!ref.view.empty()) {
                checkStabilityView(ref);
            } else if (readChartRows(ref.path).empty()) {
                throw InputError(ref.path, 0, "no rows to chart");
            }
        } catch (const InputError& e) {
            throw InputError(path, step.chartLine,
                             "step " + std::to_string(i + 1) + " chart: " + e.what());
        }
    }
    return lesson;
}

void Session::loadLesson(const std::string& path) {
    Lesson lesson = loadLessonChecked(path);
    mLesson = std::move(lesson);
    mRenderer = std::make_unique<SceneRenderer>(mLesson.scene);
    mRendered.reset();
    mSceneDirty = true;
    goToStep(0);
}

void Session::goToStep(int step) {
    if (mLesson.steps.empty()) return;
    mStep = std::clamp(step, 0, stepCount() - 1);
    const LessonStep& s = mLesson.steps[static_cast<size_t>(mStep)];
    mTextPage = 0;
    mGrid = s.settings.grid;
    setSettings(s.settings);
    setPixel(scalePixel(s.settings.pixel, glm::ivec2(mLayout.scene.size())));
    mStepEdited = false;
}

namespace {

// Equal apart from the picked pixel, which is part of the settings but not of the picture.
bool samePicture(LessonSettings a, const LessonSettings& b) {
    a.pixel = b.pixel;
    return a == b;
}

// Equal in what a step's words can talk about: also ignores a kernel size or radius the method
// does not use (a kernel change under bilinear2x2 leaves its text true).
bool sameForTheWords(LessonSettings a, const LessonSettings& b) {
    const MethodInfo& info = methodInfo(a.method);
    if (a.method == b.method && !info.usesKernel) a.kernel = b.kernel;
    if (a.method == b.method && !info.usesRadius) a.radius = b.radius;
    return samePicture(a, b);
}

}  // namespace

void Session::setSettings(const LessonSettings& s) {
    // Moving the pixel re-traces without re-rendering.
    if (!samePicture(s, mSettings) || !mRendered) mSceneDirty = true;
    mSettings = s;
    // Keys changed what the step's words were written for (goToStep clears it).
    mStepEdited = !mLesson.steps.empty() &&
                  !sameForTheWords(s, mLesson.steps[static_cast<size_t>(mStep)].settings);
}

void Session::setPixel(glm::ivec2 scenePixel) {
    glm::ivec2 size(mLayout.scene.size());
    mPixel = glm::clamp(scenePixel, glm::ivec2(0), size - glm::ivec2(1));
}

void Session::setFrameSize(glm::ivec2 frameSize) {
    if (frameSize == mLayout.frameSize && mFrame.framebuffer) return;
    glm::ivec2 oldScene(mLayout.scene.size());
    mLayout = inspectorLayout(frameSize, mPresentation);
    mFrame = createOffscreenTarget(frameSize.x, frameSize.y, {GL_RGBA8});
    glm::ivec2 newScene(mLayout.scene.size());
    if (oldScene.x > 0 && oldScene != newScene) {
        mPixel = mPixel * newScene / oldScene;
    }
    setPixel(mPixel);
    mSceneDirty = true;
}

void Session::setPresentation(bool on) {
    mPresentation = on;
    mLayout = inspectorLayout(mLayout.frameSize, on);
    mThumbnailDirty = true;
}

void Session::blitThumbnail() {
    Rect r = thumbnailRect(mLayout, mPresentation);
    int side = static_cast<int>(r.w);
    if (side <= 0 || mMap.width() <= 0) return;
    if (mThumbnailDirty || mThumbnail.width != side) {
        mThumbnail = createOffscreenTarget(side, side, {GL_RGBA8});
        std::vector<uint8_t> rgba = thumbnailImage(mMap, side);
        glTextureSubImage2D(mThumbnail.colors[0].id(), 0, 0, 0, side, side, GL_RGBA,
                            GL_UNSIGNED_BYTE, rgba.data());
        mThumbnailDirty = false;
    }
    // Texture row 0 holds the image's top row; swapped destination rows put it on top.
    int frameH = mLayout.frameSize.y;
    int x = static_cast<int>(r.x);
    int top = frameH - static_cast<int>(r.y);
    glNamedFramebufferReadBuffer(mThumbnail.framebuffer.id(), GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(mThumbnail.framebuffer.id(), mFrame.framebuffer.id(), 0, 0, side, side,
                           x, top, x + side, top - side, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

void Session::setHelp(bool on) { mHelp = on; }

bool Session::nextPage() {
    if (mTextPage + 1 >= mTextPages) return false;
    ++mTextPage;
    return true;
}

bool Session::previousPage() {
    if (mTextPage <= 0) return false;
    --mTextPage;
    return true;
}

void Session::setFrameTimeMs(double ms) { mFrameTimeMs = ms; }

void Session::blitChart(const std::string& csvPath) {
    glm::ivec2 size(mLayout.scene.size());
    std::string key = csvPath + "@" + std::to_string(size.x) + "x" + std::to_string(size.y);
    if (key != mChartKey) {
        ChartRef ref = chartRef(csvPath);
        std::vector<uint8_t> rgba;
        if (!ref.view.empty()) {
            rgba = drawStabilityView(ref, size);
        } else {
            std::vector<BenchRow> rows = readChartRows(csvPath);
            SpeedChartText labels;
            labels.title = "Speed against accuracy";
            labels.subtitle = "measured by pcfscope bench (" + rows.front().timer + "), " +
                              std::filesystem::path(csvPath).filename().string();
            rgba = drawSpeedChart(rows, size, labels);
        }
        mChart = createOffscreenTarget(size.x, size.y, {GL_RGBA8});
        glTextureSubImage2D(mChart.colors[0].id(), 0, 0, 0, size.x, size.y, GL_RGBA,
                            GL_UNSIGNED_BYTE, rgba.data());
        mChartKey = key;
    }
    // Texture row 0 holds the chart's top row; swapped destination rows put it on top.
    int frameH = mLayout.frameSize.y;
    glNamedFramebufferReadBuffer(mChart.framebuffer.id(), GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(mChart.framebuffer.id(), mFrame.framebuffer.id(), 0, 0, size.x, size.y,
                           0, frameH, size.x, frameH - size.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

void Session::renderScene() {
    RenderSettings r = renderSettingsFor(mSettings, glm::ivec2(mLayout.scene.size()));
    bool mapChanged =
        !mRendered || mRendered->mapSize != r.mapSize || mRendered->depthFormat != r.depthFormat ||
        mRendered->shadowCull != r.shadowCull || mRendered->polygonOffset != r.polygonOffset;
    if (mapChanged) mRenderer->renderShadowPass(r);
    mRenderer->renderCameraPass(r);
    if (mapChanged) {
        mMap = mRenderer->readShadowMap();
        mThumbnailDirty = true;
    }
    mRendered = r;
    mSceneDirty = false;
}

void Session::traceAtPixel() {
    mTrace.reset();
    glm::ivec2 size(mLayout.scene.size());
    // Only the region the overlay draws around the pixel comes back from the GPU.
    int radius = gridRadius(size) + 1;
    mLightSpaceOrigin = mPixel - glm::ivec2(radius);
    mLightSpaceSize = glm::ivec2(2 * radius + 1);
    mLightSpace = mRenderer->readLightSpaceRegion(mLightSpaceOrigin, mLightSpaceSize);
    size_t k = (static_cast<size_t>(radius) * mLightSpaceSize.x + radius) * 4;
    if (mLightSpace[k + 3] != 1.0f) return;
    glm::vec2 uv(mLightSpace[k], mLightSpace[k + 1]);
    float ref = mLightSpace[k + 2];
    // The receiver target holds the plane the shader used and the depth before any bias.
    std::vector<float> receiver = mRenderer->readReceiverRegion(mPixel, glm::ivec2(1));
    BiasParams bias = mSettings.biasParams();
    bias.dzduv = glm::vec2(receiver[0], receiver[1]);
    float z = receiver[3] == 1.0f ? receiver[2] : ref + mSettings.depthBias();
    mTrace = traceLookup(mMap, uv, z, ref, mSettings.pcfParams(mPixel, size), bias);
}

std::string Session::stepText() const {
    if (mLesson.steps.empty()) return "";
    const LessonStep& s = mLesson.steps[static_cast<size_t>(mStep)];
    if (!mTrace) {
        return s.text.find('{') == std::string::npos
                   ? s.text
                   : "(The picked pixel is not on a shadow receiver, so this step's numbers "
                     "cannot be shown. Pick a point on the ground.)";
    }
    StepContext ctx = makeStepContext(s, glm::ivec2(mLayout.scene.size()));
    ctx.pixel = mPixel;
    ctx.bias = mSettings.bias;
    ctx.constantBias = mSettings.constantBias;
    ctx.cull = mSettings.cull;
    ctx.depthFormat = mSettings.depthFormat;
    std::string text = fillText(s.text, *mTrace, ctx);
    // Keys may have changed the state the words were written for; the numbers follow the live
    // state, the sentences cannot. Say so rather than let them disagree in silence.
    if (mStepEdited) {
        auto compact = [](std::string t) {
            for (size_t at; (at = t.find("   ")) != std::string::npos;) t.replace(at, 3, ", ");
            return t;
        };
        text = "(Written for " + compact(settingsSummary(s.settings)) + "; now " +
               compact(settingsSummary(mSettings)) +
               ". The numbers are live; step away and back to restore the step.)\n\n" + text;
    }
    return text;
}

void Session::compose() {
    if (!mRenderer) throw std::logic_error("Session::compose before loadLesson");
    if (mSceneDirty) renderScene();
    traceAtPixel();

    GLuint fbo = mFrame.framebuffer.id();
    clearInspectorPanels(fbo, mLayout);
    // The scene goes top-left. GL rows count from the bottom, so its top edge is frame height.
    glm::ivec2 frame = mLayout.frameSize;
    glm::ivec2 scene(mLayout.scene.size());
    const std::string& chart = mLesson.steps[static_cast<size_t>(mStep)].chart;
    if (chart.empty()) {
        glNamedFramebufferReadBuffer(mRenderer->frameFramebuffer(), GL_COLOR_ATTACHMENT0);
        glBlitNamedFramebuffer(mRenderer->frameFramebuffer(), fbo, 0, 0, scene.x, scene.y, 0,
                               frame.y - scene.y, scene.x, frame.y, GL_COLOR_BUFFER_BIT,
                               GL_NEAREST);
    } else {
        blitChart(chart);
    }

    InspectorModel m = model();
    FramePlan plan = planFrame(mLayout, m);
    mTextPages = plan.textPages;
    if (mTextPage >= mTextPages) {
        // A smaller type or frame may leave fewer pages: show the last.
        mTextPage = mTextPages - 1;
        m.textPage = mTextPage;
        plan = planFrame(mLayout, m);
    }
    mBoxes = plan.boxes;
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    mCanvas.begin(frame);
    drawPlan(mCanvas, plan.base);
    mCanvas.flush();
    blitThumbnail();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    mCanvas.begin(frame);
    drawPlan(mCanvas, plan.top);
    mCanvas.flush();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

InspectorModel Session::model() const {
    glm::ivec2 scene(mLayout.scene.size());
    const std::string& chart = mLesson.steps[static_cast<size_t>(mStep)].chart;
    InspectorModel m;
    m.title = mLesson.title;
    for (const LessonStep& s : mLesson.steps) m.stepTitles.push_back(s.title);
    m.currentStep = mStep;
    m.stepText = stepText();
    m.pixel = mPixel;
    m.trace = mTrace;
    m.map = &mMap;
    m.lightSpace = &mLightSpace;
    m.lightSpaceOrigin = mLightSpaceOrigin;
    m.lightSpaceSize = mLightSpaceSize;
    m.sceneSize = scene;
    m.status = statusLine(mSettings, scene, mFrameTimeMs);
    m.presentation = mPresentation;
    m.help = mHelp;
    m.showScene = chart.empty();
    m.grid = mGrid;
    m.textPage = mTextPage;
    m.highlightFetch = mLesson.steps[static_cast<size_t>(mStep)].highlightFetch - 1;
    return m;
}

std::vector<uint8_t> Session::readFrame() const {
    return readPixelsRgba8(mFrame.framebuffer.id(), GL_COLOR_ATTACHMENT0, mFrame.width,
                           mFrame.height);
}

namespace {

// A setting as the status line and the step text print it (formatNumber: up to 4 decimals), as a
// JSON number: 0.005 stays "0.005", not the float's "0.00499999989".
Json settingNumber(float v) { return Json::parse(formatNumber(v)); }

}  // namespace

std::string Session::stepJson() const {
    const LessonSettings& s = mSettings;
    Json settings = {{"method", methodInfo(s.method).name},
                     {"kernel", s.kernel},
                     {"radius", settingNumber(s.radius)},
                     {"rotate", s.rotate},
                     {"bias", s.bias},
                     {"constant_bias", settingNumber(s.constantBias)},
                     {"cull", s.cull},
                     {"map_size", s.mapSize},
                     {"depth_format", s.depthFormat}};
    Json j = {{"lesson", mLesson.name},
              {"title", mLesson.title},
              {"step", mStep + 1},
              {"step_title", mLesson.steps.empty() ? "" : mLesson.steps[mStep].title},
              {"text", stepText()},
              {"pixel", jsonPair(mPixel)},
              {"scene_size", jsonPair(glm::ivec2(mLayout.scene.size()))},
              {"settings", settings},
              {"trace", mTrace ? traceJson(*mTrace) : Json(nullptr)},
              {"frame_size", jsonPair(mLayout.frameSize)},
              {"presentation", mPresentation},
              {"text_page", mTextPage + 1},
              {"text_pages", mTextPages},
              // inspector.h writes the layout's JSON itself (layoutJson); taken as it is.
              {"layout", Json::parse(layoutJson(mBoxes))}};
    return jsonDump(j);
}

}  // namespace pcf
