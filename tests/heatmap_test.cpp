// The viewer's aliasing heat map (A; lesson key `heatmap`): the session colours each receiver
// pixel by its screen pixels per shadow-map texel, the measure of `pcfscope stability`'s aliasing
// sweep (measure/stability.h), in the window and in exports alike (both draw Session's frame).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include "app/session.h"
#include "measure/stability.h"
#include "render/gl_context.h"
#include "run_command.h"

namespace pcf {
namespace {

class Heatmap : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    void SetUp() override { mDir = testutil::makeTempDir("heatmap"); }
    void TearDown() override {
        if (!HasFailure()) std::filesystem::remove_all(mDir);
    }
    std::string lesson(const std::string& settings) {
        std::string path = (mDir / "heat.toml").string();
        std::ofstream(path) << "title = \"heat\"\nscene = \"box-on-plane\"\n[settings]\n"
                            << settings << "\n[[step]]\ntitle = \"one\"\ntext = \"t\"\n";
        return path;
    }
    static std::unique_ptr<GlContext> sContext;
    std::filesystem::path mDir;
};
std::unique_ptr<GlContext> Heatmap::sContext;

float median(const std::vector<float>& values) {
    std::vector<float> v;
    for (float x : values) {
        if (x > 0.0f) v.push_back(x);
    }
    if (v.empty()) return 0.0f;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

TEST_F(Heatmap, ItsValuesAreTheAliasingMeasureAndFollowTheMapSize) {
    Session session({1280, 720}, false);
    session.loadLesson(lesson("heatmap = true\nmap_size = 512\ngrid = false"));
    ASSERT_TRUE(session.heatmap());
    session.compose();
    glm::ivec2 scene(session.layout().scene.size());
    std::vector<float> at512 = session.heatValues();
    ASSERT_EQ(at512.size(), static_cast<size_t>(scene.x) * scene.y);
    int measured = 0;
    for (float v : at512) measured += v > 0.0f ? 1 : 0;
    EXPECT_GT(measured, scene.x * scene.y / 4);

    // The frame shows the values in aliasingHeatColour on the receivers.
    std::vector<uint8_t> frame = session.readFrame();
    glm::ivec2 size = session.frameSize();
    int checked = 0;
    int matched = 0;
    for (int y = 0; y < scene.y * 2 / 3; y += 7) {  // above the legend
        for (int x = 0; x < scene.x; x += 7) {
            float v = at512[static_cast<size_t>(y) * scene.x + x];
            if (v <= 0.0f) continue;
            glm::vec3 c = aliasingHeatColour(v) * 255.0f;
            const uint8_t* p = &frame[(static_cast<size_t>(y) * size.x + x) * 4];
            ++checked;
            bool same = true;
            for (int i = 0; i < 3; ++i) same = same && std::fabs(p[i] - c[i]) <= 1.0f;
            matched += same ? 1 : 0;
        }
    }
    EXPECT_GT(checked, 500);
    EXPECT_GT(matched, checked * 98 / 100);  // the picked pixel's marker covers a few

    // Half the map's side: each texel covers twice the pixels each way, four times the area.
    LessonSettings s = session.settings();
    s.mapSize = 256;
    session.setSettings(s);
    session.compose();
    std::vector<float> at256 = session.heatValues();
    float ratio = median(at256) / median(at512);
    std::printf("heat map medians: map 512 %.3f, map 256 %.3f, ratio %.3f\n",
                static_cast<double>(median(at512)), static_cast<double>(median(at256)),
                static_cast<double>(ratio));
    EXPECT_NEAR(ratio, 4.0f, 0.4f);
    // The same measure the stability sweep takes from the same light-space target.
    SceneRenderer renderer(session.lesson().scene);
    RenderSettings r = renderSettingsFor(s, scene);
    // The camera as the session set it for its pinned point (a sub-pixel jitter).
    ASSERT_TRUE(session.point());
    renderer.setPick(cameraPickOf(session.lesson().scene,
                                  lessonShadowFit(session.lesson().scene, s, s.mapSize), s,
                                  *session.point(), scene));
    renderer.render(r);
    std::vector<float> direct = pixelsPerTexel(renderer.readLightSpace(), scene, 256);
    EXPECT_EQ(direct, at256);

    // Off: the scene as rendered, no values.
    session.setHeatmap(false);
    session.compose();
    EXPECT_TRUE(session.heatValues().empty());
}

TEST_F(Heatmap, ALessonKeyThatIsNotABooleanIsRefused) {
    auto r =
        testutil::runPcfscope("export " + lesson("heatmap = 3") + " -o " + (mDir / "out").string());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("heatmap must be true or false"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(mDir / "out"));
}

}  // namespace
}  // namespace pcf
