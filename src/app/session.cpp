#include "app/session.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "analysis/bench_report.h"
#include "analysis/speed_chart.h"
#include "analysis/stability.h"
#include "analysis/stability_chart.h"
#include "analysis/stability_report.h"
#include "app/cli_util.h"
#include "base/input_error.h"
#include "base/input_file.h"
#include "kernel/methods.h"
#include "kernel/trace_explain.h"
#include "kernel/trace_json.h"
#include "lesson/lesson_text.h"
#include "scene/light.h"

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
    line << "   bias " << biasModeName(s.bias);
    if (s.bias != BiasMode::None) line << " " << formatNumber(s.constantBias);
    if (s.bias == BiasMode::Slope) {
        line << " +" << formatNumber(s.slopeBias) << "tan<=" << formatNumber(s.slopeMax);
    }
    if (s.bias == BiasMode::Normal) line << " k=" << formatNumber(s.normalOffset);
    if (s.bias == BiasMode::Soft) line << " x" << formatNumber(s.softScale);
    if (s.bias == BiasMode::ReceiverPlane) line << " dz<=" << formatNumber(s.rpdbMax);
    line << "   cull " << cullModeName(s.cull) << "   map " << s.mapSize << " "
         << depthFormatName(s.depthFormat);
    if (s.originShift != 0.0f || s.snap) {
        line << "   grid +" << formatNumber(s.originShift) << " texel"
             << (s.snap ? " snapped" : "");
    }
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

std::optional<std::string> findLesson(const std::vector<std::string>& lessons,
                                      const std::string& nameOrNumber) {
    // A number names the file numbered so (13 -> 13-*.toml, also "013"), never the 13th file:
    // a lesson directory with a gap (no 12) would shift every lesson after it.
    bool number = !nameOrNumber.empty() && nameOrNumber.size() <= 6 &&
                  std::all_of(nameOrNumber.begin(), nameOrNumber.end(),
                              [](char c) { return c >= '0' && c <= '9'; });
    for (const std::string& path : lessons) {
        std::string stem = std::filesystem::path(path).stem().string();
        if (stem == nameOrNumber) return path;
        if (!number) continue;
        size_t digits = 0;
        while (digits < stem.size() && digits < 6 && stem[digits] >= '0' && stem[digits] <= '9') {
            ++digits;
        }
        if (digits > 0 && std::stoi(stem.substr(0, digits)) == std::stoi(nameOrNumber)) {
            return path;
        }
    }
    return std::nullopt;
}

std::string resolveLesson(const std::string& nameOrPath) {
    if (nameOrPath.find('/') != std::string::npos || nameOrPath.ends_with(".toml")) {
        return nameOrPath;  // a path: parseLessonFile says what is wrong with it
    }
    std::vector<std::string> lessons = builtInLessons();
    if (std::optional<std::string> found = findLesson(lessons, nameOrPath)) return *found;
    std::string names;
    for (const std::string& path : lessons) {
        names += (names.empty() ? "" : ", ") + std::filesystem::path(path).stem().string();
    }
    throw UsageError("unknown lesson '" + nameOrPath + "' (a .toml path, a lesson's number, " +
                     "or one of: " + names + ")");
}

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
    r.depthFormat = s.depthFormat;
    r.bias = s.bias;
    r.constantBias = s.constantBias;
    r.slopeBias = s.slopeBias;
    r.slopeMax = s.slopeMax;
    r.normalOffset = s.normalOffset;
    r.softScale = s.softScale;
    r.rpdbMax = s.rpdbMax;
    r.shadowCull = s.cull;
    r.frameSize = sceneSize;
    return r;
}

glm::mat4 lessonShadowFit(const Scene& scene, const LessonSettings& s, int mapSize) {
    glm::mat4 fit = shadowClipFromWorld(scene);
    if (s.originShift == 0.0f && !s.snap) return fit;
    return shiftShadowOrigin(fit, glm::vec2(s.originShift), mapSize, s.snap);
}

Session::Session(glm::ivec2 frameSize, bool presentation) : mPresentation(presentation) {
    setFrameSize(frameSize);
}

namespace {

// A chart's CSV, read with the checks every input file gets (base/input_file.h).
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

std::string stabilitySubtitle(const ChartRef& ref) {
    return "measured by pcfscope stability, " + std::filesystem::path(ref.path).filename().string();
}

// The stability chart `view` of a stability.csv, or InputError for an unknown view or no rows.
std::vector<uint8_t> drawStabilityView(const ChartRef& ref, glm::ivec2 size,
                                       float minFontPx = 8.0f) {
    std::vector<StabilityRow> rows = readStabilityRows(ref.path);
    std::string subtitle = stabilitySubtitle(ref);
    std::vector<uint8_t> rgba;
    if (ref.view == "acne") {
        rgba = drawAcneChart(rows, size, subtitle, minFontPx);
    } else if (ref.view == "leak") {
        rgba = drawLeakChart(rows, size, subtitle, minFontPx);
    } else if (ref.view == "shimmer") {
        rgba = drawShimmerChart(rows, size, subtitle, minFontPx);
    } else {
        throw InputError(
            ref.path, 0,
            "unknown stability chart '#" + ref.view + "' (known: #acne, #leak, #shimmer)");
    }
    if (rgba.empty()) throw InputError(ref.path, 0, "no " + ref.view + " rows to chart");
    return rgba;
}

// The texts of the stability chart `view` (where drawStabilityView draws them).
std::vector<ChartTextBox> stabilityViewTextBoxes(const ChartRef& ref, glm::ivec2 size,
                                                 float minFontPx) {
    std::vector<StabilityRow> rows = readStabilityRows(ref.path);
    std::string subtitle = stabilitySubtitle(ref);
    if (ref.view == "acne")
        return lineChartTextBoxes(acneChartSpec(rows, subtitle, minFontPx), size);
    if (ref.view == "leak")
        return lineChartTextBoxes(leakChartSpec(rows, subtitle, minFontPx), size);
    if (ref.view == "shimmer") {
        return barChartTextBoxes(shimmerChartSpec(rows, subtitle, minFontPx), size);
    }
    return {};
}

// Throws InputError unless the stability.csv has rows for the view.
void checkStabilityView(const ChartRef& ref) {
    std::vector<StabilityRow> rows = readStabilityRows(ref.path);
    if (ref.view != "acne" && ref.view != "leak" && ref.view != "shimmer") {
        throw InputError(
            ref.path, 0,
            "unknown stability chart '#" + ref.view + "' (known: #acne, #leak, #shimmer)");
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
        if (step.chartHighlight.empty()) continue;
        try {
            chartRowsMatching(readChartRows(chartRef(step.chart).path), step.chartHighlight);
        } catch (const std::invalid_argument& e) {
            throw InputError(path, step.chartHighlightLine,
                             "step " + std::to_string(i + 1) + " chart_highlight: " + e.what());
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
    mHeatmap = s.settings.heatmap;
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

bool Session::sceneShown() const {
    return mLesson.steps.empty() || mLesson.steps[static_cast<size_t>(mStep)].chart.empty();
}

bool Session::clickFrame(glm::vec2 framePoint) {
    const Rect& scene = mLayout.scene;
    if (!sceneShown() || !scene.contains(framePoint)) return false;
    setPixel(glm::ivec2(framePoint - scene.position()));
    return true;
}

void Session::setFrameSize(glm::ivec2 frameSize) {
    if (frameSize == mLayout.frameSize && mFrame.framebuffer) return;
    glm::ivec2 oldScene(mLayout.scene.size());
    mLayout = inspectorLayout(frameSize, mPresentation);
    if (mSceneOnly) mLayout.scene = Rect{0.0f, 0.0f, float(frameSize.x), float(frameSize.y)};
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

namespace {

// Uploads a top-down RGBA8 image with its rows reversed, so that texture row 0 is the image's
// bottom row, as GL counts rows. The frame then takes it with an unflipped blit, which llvmpipe
// copies as memory instead of running a shader over every pixel; the bytes are the same.
void uploadBottomUp(const OffscreenTarget& target, int w, int h, const std::vector<uint8_t>& rgba) {
    std::vector<uint8_t> flipped(rgba.size());
    size_t row = static_cast<size_t>(w) * 4;
    for (int y = 0; y < h; ++y) {
        std::copy_n(
            rgba.begin() + static_cast<std::ptrdiff_t>(row * static_cast<size_t>(h - 1 - y)), row,
            flipped.begin() + static_cast<std::ptrdiff_t>(row * static_cast<size_t>(y)));
    }
    glTextureSubImage2D(target.colors[0].id(), 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE,
                        flipped.data());
}

}  // namespace

void Session::blitThumbnail() {
    Rect r = thumbnailRect(mLayout, mPresentation);
    int side = static_cast<int>(r.w);
    if (side <= 0 || mMap.width() <= 0) return;
    if (mThumbnailDirty || mThumbnail.width != side) {
        mThumbnail = createOffscreenTarget(side, side, {GL_RGBA8});
        std::vector<uint8_t> rgba = thumbnailImage(mMap, side);
        uploadBottomUp(mThumbnail, side, side, rgba);
        mThumbnailDirty = false;
    }
    // Texture row 0 holds the image's bottom row (uploadBottomUp): a straight copy.
    int frameH = mLayout.frameSize.y;
    int x = static_cast<int>(r.x);
    int top = frameH - static_cast<int>(r.y);
    glNamedFramebufferReadBuffer(mThumbnail.framebuffer.id(), GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(mThumbnail.framebuffer.id(), mTarget, 0, 0, side, side, x, top - side,
                           x + side, top, GL_COLOR_BUFFER_BIT, GL_NEAREST);
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

namespace {

// A chart step's smallest type: the frame's floors for numbers and labels (inspector.h:
// typeSizes), so that the chart reads as well as the text beside it.
float chartFloor(bool presentation) {
    InspectorLayout frame;
    frame.presentation = presentation;
    TypeSizes t = typeSizes(frame);
    return std::max(t.numberFloor, t.labelFloor);
}

// The chart's text and type for a speed-chart step.
SpeedChartText stepChartText(const LessonStep& step, const std::vector<BenchRow>& rows,
                             bool presentation) {
    SpeedChartText labels;
    labels.title = "Speed against accuracy";
    labels.subtitle = "measured by pcfscope bench (" + rows.front().timer + "), " +
                      std::filesystem::path(step.chart).filename().string();
    if (!step.chartHighlight.empty())
        labels.highlight = chartRowsMatching(rows, step.chartHighlight);
    labels.minFontPx = chartFloor(presentation);
    // A projector's chart names only what the step talks about.
    labels.keptLabelsOnly = presentation;
    return labels;
}

}  // namespace

std::vector<uint8_t> drawStepChart(const LessonStep& step, glm::ivec2 size, bool presentation) {
    ChartRef ref = chartRef(step.chart);
    if (!ref.view.empty()) return drawStabilityView(ref, size, chartFloor(presentation));
    std::vector<BenchRow> rows = readChartRows(step.chart);
    return drawSpeedChart(rows, size, stepChartText(step, rows, presentation));
}

std::vector<LayoutBox> stepChartBoxes(const LessonStep& step, const InspectorLayout& layout) {
    std::vector<LayoutBox> out;
    ChartRef ref = chartRef(step.chart);
    if (step.chart.empty()) return out;
    glm::ivec2 size(layout.scene.size());
    std::vector<ChartTextBox> texts;
    if (!ref.view.empty()) {
        texts = stabilityViewTextBoxes(ref, size, chartFloor(layout.presentation));
    } else {
        std::vector<BenchRow> rows = readChartRows(step.chart);
        SpeedChartText text = stepChartText(step, rows, layout.presentation);
        SpeedChartLayout L =
            layoutSpeedChart(rows, size, ChartTiming::Scene, ChartAccuracy::EdgeRmse,
                             text.highlight, text.minFontPx, text.keptLabelsOnly);
        texts = speedChartTextBoxes(L, text);
    }
    for (const ChartTextBox& b : texts) {
        BoxKind kind = b.role == "chart-tick"                                ? BoxKind::Number
                       : b.role == "chart-label" || b.role == "chart-legend" ? BoxKind::Label
                                                                             : BoxKind::Text;
        Rect r{b.rect.x + layout.scene.x, b.rect.y + layout.scene.y, b.rect.w, b.rect.h};
        out.push_back({kind, r, "scene", b.role, b.fontPx, false, b.text});
    }
    return out;
}

void Session::blitChart(const InspectorLayout& layout) {
    glm::ivec2 size(layout.scene.size());
    const LessonStep& step = mLesson.steps[static_cast<size_t>(mStep)];
    // The chart's texts are placed with the scene rect's origin, so the key has it too.
    std::string key = step.chart + "@" + std::to_string(size.x) + "x" + std::to_string(size.y) +
                      "+" + std::to_string(layout.scene.x) + "," + std::to_string(layout.scene.y) +
                      "#" + step.chartHighlight + (layout.presentation ? "P" : "");
    if (key != mChartKey) {
        std::vector<uint8_t> rgba = drawStepChart(step, size, layout.presentation);
        mChart = createOffscreenTarget(size.x, size.y, {GL_RGBA8});
        uploadBottomUp(mChart, size.x, size.y, rgba);
        mChartBoxes = stepChartBoxes(step, layout);
        mChartKey = key;
    }
    // Texture row 0 holds the chart's bottom row (uploadBottomUp): a straight copy.
    int frameH = mLayout.frameSize.y;
    int x = static_cast<int>(layout.scene.x);
    int top = frameH - static_cast<int>(layout.scene.y);
    glNamedFramebufferReadBuffer(mChart.framebuffer.id(), GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(mChart.framebuffer.id(), mTarget, 0, 0, size.x, size.y, x, top - size.y,
                           x + size.x, top, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

void Session::renderScene() {
    RenderSettings r = renderSettingsFor(mSettings, glm::ivec2(mLayout.scene.size()));
    // The map's texel grid slid and snapped as the lesson says (light.h: shiftShadowOrigin).
    glm::vec3 shift(mSettings.originShift, mSettings.originShift, mSettings.snap ? 1.0f : 0.0f);
    bool mapChanged = !mRendered || mRendered->mapSize != r.mapSize ||
                      mRendered->depthFormat != r.depthFormat ||
                      mRendered->shadowCull != r.shadowCull ||
                      mRendered->polygonOffset != r.polygonOffset || shift != mRenderedShift;
    if (mapChanged) {
        mRenderer->setShadowClipFromWorld(
            mShadowFit ? *mShadowFit : lessonShadowFit(mLesson.scene, mSettings, r.mapSize));
        mRenderedShift = shift;
    }
    mHeatDirty = true;
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
    mLookup = glm::vec3(uv, z);
    mLookupRef = ref;
    mLookupBias = bias;
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

void Session::compose() { composeInto(mFrame.framebuffer.id()); }

void Session::composeInto(GLuint fbo) {
    if (!mRenderer) throw std::logic_error("Session::compose before loadLesson");
    if (mSceneDirty) renderScene();
    traceAtPixel();
    if (mSceneOnly) return composeSceneOnly(fbo);

    mTarget = fbo;
    const LessonStep& step = mLesson.steps[static_cast<size_t>(mStep)];
    const std::string& chart = step.chart;
    // A chart step in presentation mode gives the chart the inspector's room too.
    InspectorLayout layout = chart.empty() ? mLayout : chartStepLayout(mLayout);
    clearInspectorPanels(fbo, layout);
    // The scene goes top-left. GL rows count from the bottom, so its top edge is frame height.
    glm::ivec2 frame = mLayout.frameSize;
    glm::ivec2 scene(mLayout.scene.size());
    if (chart.empty()) {
        glNamedFramebufferReadBuffer(mRenderer->frameFramebuffer(), GL_COLOR_ATTACHMENT0);
        glBlitNamedFramebuffer(mRenderer->frameFramebuffer(), fbo, 0, 0, scene.x, scene.y, 0,
                               frame.y - scene.y, scene.x, frame.y, GL_COLOR_BUFFER_BIT,
                               GL_NEAREST);
        if (mHeatmap) blitHeatmap();
    } else {
        blitChart(layout);
    }

    InspectorModel m = model();
    FramePlan plan = planFrame(layout, m);
    mTextPages = plan.textPages;
    if (mTextPage >= mTextPages) {
        // A smaller type or frame may leave fewer pages: show the last.
        mTextPage = mTextPages - 1;
        m.textPage = mTextPage;
        plan = planFrame(layout, m);
    }
    mBoxes = plan.boxes;
    // blitChart above placed them with the chart it drew or kept.
    if (!chart.empty()) mBoxes.insert(mBoxes.end(), mChartBoxes.begin(), mChartBoxes.end());
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    mCanvas.begin(frame);
    drawPlan(mCanvas, plan.base);
    mCanvas.flush();
    blitThumbnail();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    mCanvas.begin(frame);
    drawPlan(mCanvas, plan.top);
    if (mHeatmap && chart.empty()) drawHeatLegend();
    if (mFlicker && chart.empty()) drawFlicker();
    mCanvas.flush();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!mHeatmap || !chart.empty()) mHeatValues.clear();
}

// The heat map replaces the scene on its receivers (each pixel the colour of its pixels per
// texel); elsewhere the scene stays. Computed once per rendered scene: moving the pixel reuses it.
void Session::blitHeatmap() {
    glm::ivec2 size(mLayout.scene.size());
    if (mHeatDirty || mHeat.width != size.x || mHeat.height != size.y) {
        mHeatValues = pixelsPerTexel(mRenderer->readLightSpace(), size, mRendered->mapSize);
        std::vector<uint8_t> rgba = mRenderer->readColour();
        for (size_t k = 0; k < mHeatValues.size(); ++k) {
            if (mHeatValues[k] <= 0.0f) continue;
            glm::vec3 c = aliasingHeatColour(mHeatValues[k]);
            for (int i = 0; i < 3; ++i) {
                rgba[k * 4 + i] = static_cast<uint8_t>(std::lround(c[i] * 255.0f));
            }
        }
        mHeat = createOffscreenTarget(size.x, size.y, {GL_RGBA8});
        uploadBottomUp(mHeat, size.x, size.y, rgba);
        mHeatDirty = false;
    }
    // Texture row 0 holds the image's bottom row (uploadBottomUp): a straight copy.
    int frameH = mLayout.frameSize.y;
    glNamedFramebufferReadBuffer(mHeat.framebuffer.id(), GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(mHeat.framebuffer.id(), mTarget, 0, 0, size.x, size.y, 0,
                           frameH - size.y, size.x, frameH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

// The legend in the scene's bottom-left corner: the colour ramp from 1/16 to 16 screen pixels
// per texel, and the median over the receivers.
void Session::drawHeatLegend() {
    const Rect& scene = mLayout.scene;
    float font = std::max(12.0f, std::round((mPresentation ? 18.0f : 14.0f) * mLayout.scale));
    std::vector<float> measured;
    for (float v : mHeatValues) {
        if (v > 0.0f) measured.push_back(v);
    }
    std::string title = "screen pixels per texel";
    if (!measured.empty()) {
        std::nth_element(measured.begin(), measured.begin() + measured.size() / 2, measured.end());
        char median[32];
        std::snprintf(median, sizeof median, ", median %.3g",
                      static_cast<double>(measured[measured.size() / 2]));
        title += median;
    }
    float pad = std::round(font * 0.6f);
    float lineH = std::round(font * 1.35f);
    float barH = std::round(font * 0.9f);
    float barW = std::max(std::round(font * 14.0f), measureText(FontFace::Sans, font, title).x);
    barW = std::min(barW, scene.w - 4.0f * pad);
    Rect box{scene.x + pad, 0.0f, barW + 2.0f * pad, 2.0f * pad + 2.0f * lineH + barH};
    box.y = scene.y + scene.h - pad - box.h;
    mCanvas.fillRect(box, {0.08f, 0.09f, 0.11f, 0.85f});
    TextStyle text{FontFace::Sans, font, {0.92f, 0.93f, 0.95f, 1.0f}};
    mCanvas.text({box.x + pad, box.y + pad}, title, text);
    float barY = box.y + pad + lineH;
    const int steps = 64;
    for (int i = 0; i < steps; ++i) {
        float x0 = std::round(box.x + pad + barW * i / steps);
        float x1 = std::round(box.x + pad + barW * (i + 1) / steps);
        float t = (i + 0.5f) / steps * 2.0f - 1.0f;  // log2 / range, -1 .. 1
        glm::vec3 c = aliasingHeatColour(std::exp2(t * ALIASING_HEAT_LOG2_RANGE));
        mCanvas.fillRect({x0, barY, x1 - x0, barH}, {c, 1.0f});
    }
    float labelY = barY + barH + std::round(font * 0.2f);
    mCanvas.text({box.x + pad, labelY}, "1/16", text);
    TextStyle centre = text;
    centre.align = TextAlign::Center;
    mCanvas.text({box.x + pad + barW / 2.0f, labelY}, "1", centre);
    TextStyle right = text;
    right.align = TextAlign::Right;
    mCanvas.text({box.x + pad + barW, labelY}, "16", right);
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

// The frame's layout (planFrame's boxes) as a JSON array: [{"kind", "panel", "role",
// "rect": [x, y, w, h], "font_px", "shortened"}, ...]; font_px and shortened only for what
// draws text.
Json layoutJson(const std::vector<LayoutBox>& boxes) {
    Json out = Json::array();
    for (const LayoutBox& b : boxes) {
        Json box = {{"kind", boxKindName(b.kind)},
                    {"panel", b.panel},
                    {"role", b.role},
                    {"rect", Json::array({jsonNumber(b.rect.x), jsonNumber(b.rect.y),
                                          jsonNumber(b.rect.w), jsonNumber(b.rect.h)})}};
        if (b.kind == BoxKind::Text || b.kind == BoxKind::Number || b.kind == BoxKind::Label ||
            b.fontPx > 0.0f) {
            box["font_px"] = jsonNumber(b.fontPx);
            box["shortened"] = b.shortened;
        }
        out.push_back(std::move(box));
    }
    return out;
}

}  // namespace

std::string Session::stepJson() const {
    const LessonSettings& s = mSettings;
    Json settings = {{"method", methodInfo(s.method).name},
                     {"kernel", s.kernel},
                     {"radius", settingNumber(s.radius)},
                     {"rotate", s.rotate},
                     {"bias", biasModeName(s.bias)},
                     {"constant_bias", settingNumber(s.constantBias)},
                     {"cull", cullModeName(s.cull)},
                     {"map_size", s.mapSize},
                     {"depth_format", depthFormatName(s.depthFormat)}};
    Json j = {{"lesson", mLesson.name},
              {"title", mLesson.title},
              {"step", mStep + 1},
              {"step_title", mLesson.steps.empty() ? "" : mLesson.steps[mStep].title},
              {"text", drawnStepText(stepText())},
              {"pixel", jsonPair(mPixel)},
              {"scene_size", jsonPair(glm::ivec2(mLayout.scene.size()))},
              {"settings", settings},
              {"trace", mTrace ? traceJson(*mTrace) : Json(nullptr)},
              {"frame_size", jsonPair(mLayout.frameSize)},
              {"presentation", mPresentation},
              {"text_page", mTextPage + 1},
              {"text_pages", mTextPages},
              {"layout", layoutJson(mBoxes)}};
    return jsonDump(j);
}

}  // namespace pcf
