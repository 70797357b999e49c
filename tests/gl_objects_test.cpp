// GL object ownership, offscreen targets, and the row order of every readback.
#include "render/gl_objects.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>

#include "kernel/shadow_map.h"
#include "render/gl_context.h"
#include "render/shader_loader.h"

namespace pcf {
namespace {

class GlObjects : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { sContext = createHeadlessContext(); }
    static void TearDownTestSuite() { sContext.reset(); }
    void SetUp() override { sContext->makeCurrent(); }

    static std::unique_ptr<GlContext> sContext;
};

std::unique_ptr<GlContext> GlObjects::sContext;

// One triangle, corners in NDC from gl_VertexID: (-1,-3), (-1,0), (5,0). Its top edge is
// y = 0 and it covers all of x in [-1,1] for y in [-1,0]: exactly the lower half of the target.
const char* LOWER_HALF_VERT = R"(
const vec2 CORNERS[3] = vec2[3](vec2(-1.0, -3.0), vec2(-1.0, 0.0), vec2(5.0, 0.0));
void main() { gl_Position = vec4(CORNERS[gl_VertexID], 0.0, 1.0); }
)";

const char* RED_FRAG = R"(
layout(location = 0) out vec4 outColor;
layout(location = 1) out float outRed;
void main() {
    outColor = vec4(1.0, 0.0, 0.0, 1.0);
    outRed = 1.0;
}
)";

// Covers the whole target; each fragment writes a depth that names its row:
// (row + 0.5) / height, with row counted the GL way (0 = bottom).
const char* FULL_VERT = R"(
const vec2 CORNERS[3] = vec2[3](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
void main() { gl_Position = vec4(CORNERS[gl_VertexID], 0.5, 1.0); }
)";

const char* ROW_DEPTH_FRAG = R"(
uniform float uHeight;
void main() { gl_FragDepth = gl_FragCoord.y / uHeight; }
)";

TEST_F(GlObjects, MovesTransferOwnershipAndResetDeletes) {
    GlTexture a = createTexture2d(GL_RGBA8, 4, 4);
    GLuint id = a.id();
    ASSERT_NE(id, 0u);
    EXPECT_TRUE(glIsTexture(id));
    GlTexture b = std::move(a);
    EXPECT_EQ(a.id(), 0u);  // NOLINT(bugprone-use-after-move): checking the moved-from state
    EXPECT_FALSE(static_cast<bool>(a));
    EXPECT_EQ(b.id(), id);
    GlTexture c;
    c = std::move(b);
    EXPECT_EQ(c.id(), id);
    c.reset();
    EXPECT_EQ(c.id(), 0u);
    EXPECT_FALSE(glIsTexture(id));
    {
        GlBuffer buffer = createBuffer();
        id = buffer.id();
        EXPECT_TRUE(glIsBuffer(id));
    }
    EXPECT_FALSE(glIsBuffer(id));
}

TEST_F(GlObjects, ClearedTargetReadsBackThatExactColour) {
    OffscreenTarget t =
        createOffscreenTarget(5, 3, {GL_RGBA8, GL_RGBA32F, GL_R32F}, GL_DEPTH_COMPONENT32F);
    ASSERT_EQ(t.colors.size(), 3u);
    ASSERT_TRUE(t.depth);
    const float rgba8[4] = {0.2f, 0.4f, 0.6f, 1.0f};
    const float rgba32f[4] = {0.125f, -2.5f, 1.0e6f, 0.75f};
    const float r32f[4] = {0.3333333f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(t.framebuffer.id(), GL_COLOR, 0, rgba8);
    glClearNamedFramebufferfv(t.framebuffer.id(), GL_COLOR, 1, rgba32f);
    glClearNamedFramebufferfv(t.framebuffer.id(), GL_COLOR, 2, r32f);

    std::vector<uint8_t> bytes = readPixelsRgba8(t.framebuffer.id(), GL_COLOR_ATTACHMENT0, 5, 3);
    ASSERT_EQ(bytes.size(), 5u * 3u * 4u);
    for (size_t k = 0; k < bytes.size(); k += 4) {
        EXPECT_EQ(bytes[k + 0], 51);  // 0.2 * 255
        EXPECT_EQ(bytes[k + 1], 102);
        EXPECT_EQ(bytes[k + 2], 153);
        EXPECT_EQ(bytes[k + 3], 255);
    }
    std::vector<float> floats = readPixelsFloat(t.framebuffer.id(), GL_COLOR_ATTACHMENT1, 5, 3, 4);
    ASSERT_EQ(floats.size(), 5u * 3u * 4u);
    for (size_t k = 0; k < floats.size(); k += 4) {
        EXPECT_EQ(floats[k + 0], 0.125f);
        EXPECT_EQ(floats[k + 1], -2.5f);
        EXPECT_EQ(floats[k + 2], 1.0e6f);
        EXPECT_EQ(floats[k + 3], 0.75f);
    }
    std::vector<float> single = readPixelsFloat(t.framebuffer.id(), GL_COLOR_ATTACHMENT2, 5, 3, 1);
    ASSERT_EQ(single.size(), 5u * 3u);
    for (float v : single) EXPECT_EQ(v, 0.3333333f);
}

// Pins the TOP-DOWN convention: a triangle over the lower half of the picture must come back
// in the LAST rows of the readback.
TEST_F(GlObjects, ReadbackRowsAreTopDown) {
    const int w = 8;
    const int h = 6;
    OffscreenTarget t = createOffscreenTarget(w, h, {GL_RGBA8, GL_R32F});
    GlProgram program =
        buildProgram({{GL_VERTEX_SHADER, {}, "", {{"lower_half.vert", LOWER_HALF_VERT}}},
                      {GL_FRAGMENT_SHADER, {}, "", {{"red.frag", RED_FRAG}}}});
    GlVertexArray vao = createVertexArray();
    glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer.id());
    glViewport(0, 0, w, h);
    const float clear[4] = {0.0f, 0.0f, 1.0f, 1.0f};
    glClearNamedFramebufferfv(t.framebuffer.id(), GL_COLOR, 0, clear);
    glClearNamedFramebufferfv(t.framebuffer.id(), GL_COLOR, 1, clear);
    glUseProgram(program.id());
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    std::vector<uint8_t> rgba = readPixelsRgba8(t.framebuffer.id(), GL_COLOR_ATTACHMENT0, w, h);
    std::vector<float> red = readPixelsFloat(t.framebuffer.id(), GL_COLOR_ATTACHMENT1, w, h, 1);
    for (int row = 0; row < h; ++row) {
        bool filled = row >= h / 2;  // top-down: the lower half is the last rows
        for (int x = 0; x < w; ++x) {
            size_t p = static_cast<size_t>(row) * w + x;
            EXPECT_EQ(rgba[4 * p + 0], filled ? 255 : 0) << "row " << row << " x " << x;
            EXPECT_EQ(rgba[4 * p + 2], filled ? 0 : 255) << "row " << row << " x " << x;
            EXPECT_EQ(red[p], filled ? 1.0f : 0.0f) << "row " << row << " x " << x;
        }
    }
}

TEST_F(GlObjects, UploadedDepthTextureReadsBackInGlRowOrder) {
    const int w = 5;
    const int h = 4;
    ShadowMap map(w, h);
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) map.setDepth(i, j, static_cast<float>(j * w + i) / 32.0f);
    }
    GlTexture texture = createDepthTexture(map);
    std::vector<float> back = readDepthTexture(texture.id(), w, h);
    ASSERT_EQ(back, map.depths());
    // And texelFetch sees ShadowMap's (i, j) at GL texel (i, j): read one texel as a colour.
    GlFramebuffer fbo = createFramebuffer();
    glNamedFramebufferTexture(fbo.id(), GL_DEPTH_ATTACHMENT, texture.id(), 0);
    glNamedFramebufferReadBuffer(fbo.id(), GL_NONE);
    glNamedFramebufferDrawBuffer(fbo.id(), GL_NONE);
    checkFramebufferComplete(fbo.id(), "depth readback");
    float texel = -1.0f;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo.id());
    glReadPixels(3, 2, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &texel);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    EXPECT_EQ(texel, map.depth(3, 2));
}

// A depth written by rendering (the shadow pass's way) comes back with row 0 = the bottom row,
// for every depth format, to the format's precision.
TEST_F(GlObjects, RenderedDepthReadsBackInGlRowOrderForEveryFormat) {
    const int w = 3;
    const int h = 8;
    GlProgram program =
        buildProgram({{GL_VERTEX_SHADER, {}, "", {{"full.vert", FULL_VERT}}},
                      {GL_FRAGMENT_SHADER, {}, "", {{"row_depth.frag", ROW_DEPTH_FRAG}}}});
    GlVertexArray vao = createVertexArray();
    struct Format {
        GLenum format;
        float tolerance;
    };
    for (Format f :
         {Format{GL_DEPTH_COMPONENT16, 2.0f / 65535.0f},
          Format{GL_DEPTH_COMPONENT24, 2.0f / 16777215.0f}, Format{GL_DEPTH_COMPONENT32F, 0.0f}}) {
        OffscreenTarget t = createOffscreenTarget(w, h, {}, f.format);
        glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer.id());
        glViewport(0, 0, w, h);
        glClearDepth(1.0);
        glClear(GL_DEPTH_BUFFER_BIT);
        // Depth writes need the depth test on; ALWAYS lets every fragment through.
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_ALWAYS);
        glUseProgram(program.id());
        glUniform1f(glGetUniformLocation(program.id(), "uHeight"), static_cast<float>(h));
        glBindVertexArray(vao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glUseProgram(0);
        glDisable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);

        std::vector<float> depth = readDepthTexture(t.depth.id(), w, h);
        ASSERT_EQ(depth.size(), static_cast<size_t>(w * h));
        for (int j = 0; j < h; ++j) {
            for (int i = 0; i < w; ++i) {
                float expected = (static_cast<float>(j) + 0.5f) / static_cast<float>(h);
                EXPECT_NEAR(depth[static_cast<size_t>(j) * w + i], expected, f.tolerance)
                    << "format 0x" << std::hex << f.format << std::dec << " texel (" << i << ", "
                    << j << ")";
            }
        }
    }
}

TEST_F(GlObjects, IncompleteFramebufferThrowsWithTheStatusName) {
    GlFramebuffer empty = createFramebuffer();
    try {
        checkFramebufferComplete(empty.id(), "empty");
        FAIL() << "an attachment-less framebuffer passed the completeness check";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(
            e.what(),
            "framebuffer empty is incomplete: GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT");
    }
    // A colour format is not a depth format: GL refuses the attachment, the check says so.
    GlTexture color = createTexture2d(GL_RGBA8, 2, 2);
    GlFramebuffer wrong = createFramebuffer();
    glNamedFramebufferTexture(wrong.id(), GL_DEPTH_ATTACHMENT, color.id(), 0);
    EXPECT_THROW(checkFramebufferComplete(wrong.id(), "wrong"), std::runtime_error);
    while (glGetError() != GL_NO_ERROR) {
    }
    EXPECT_EQ(framebufferStatusName(GL_FRAMEBUFFER_UNSUPPORTED), "GL_FRAMEBUFFER_UNSUPPORTED");
    EXPECT_EQ(framebufferStatusName(0x1234), "0x1234");
}

TEST_F(GlObjects, DepthOnlyTargetIsComplete) {
    OffscreenTarget t = createOffscreenTarget(16, 16, {}, GL_DEPTH_COMPONENT24);
    EXPECT_TRUE(t.colors.empty());
    EXPECT_TRUE(t.depth);
    EXPECT_EQ(glCheckNamedFramebufferStatus(t.framebuffer.id(), GL_FRAMEBUFFER),
              static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
}

TEST_F(GlObjects, ReadbackLeavesPackStateAlone) {
    OffscreenTarget t = createOffscreenTarget(3, 3, {GL_RGBA8});
    GlFramebuffer other = createFramebuffer();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, other.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    std::vector<uint8_t> px = readPixelsRgba8(t.framebuffer.id(), GL_COLOR_ATTACHMENT0, 3, 3);
    EXPECT_EQ(px.size(), 36u);
    GLint binding = 0;
    GLint alignment = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &binding);
    glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
    EXPECT_EQ(static_cast<GLuint>(binding), other.id());
    EXPECT_EQ(alignment, 8);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
}

TEST(FlipRows, ReversesRowOrder) {
    std::vector<int> v = {1, 2, 3, 4, 5, 6};
    flipRows(v, 2, 3);
    EXPECT_EQ(v, (std::vector<int>{5, 6, 3, 4, 1, 2}));
    flipRows(v, 3, 2);
    EXPECT_EQ(v, (std::vector<int>{4, 1, 2, 5, 6, 3}));
    std::vector<int> one = {7, 8};
    flipRows(one, 2, 1);
    EXPECT_EQ(one, (std::vector<int>{7, 8}));
}

}  // namespace
}  // namespace pcf
