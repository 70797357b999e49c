// lesson_text.h: the live text of a lesson step. A step's text names the numbers it talks about
// as placeholders; fillText replaces them with the numbers of the trace of the picked pixel, so
// the words can never disagree with the math the kernel did.
//
// Syntax: {name} writes the value as the trace's steps do (formatNumber: up to 4 decimals,
// trailing zeros trimmed, "0.8"); {name:N} writes it with exactly N decimals (N = 0..9,
// "{frac.x:3}" -> "0.200"); {name*F} multiplies it by the number F first, e.g. "{weight[0,0]*9}"
// for the table of "PCF Shadow Acne 2" in ninths (both may be combined: "{weight[1,1]*9:2}").
// {{ and }} are a literal { and }.
//
// Names (every number is the traced lookup's; "texel space" is the map's texel grid):
//   uv.x uv.y             where the pixel lands in the shadow map, in [0,1]
//   z                     the receiver's light depth before bias
//   ref                   the depth compared with the map (after bias)
//   depth_bias            z - ref
//   texel.x texel.y       the continuous texel position p = uv * size - 0.5
//   base.x base.y         floor(p): the lower corner of the bilinear 2x2
//   frac.x frac.y         p - base: the sub-texel position that weights the lerp
//   1-frac.x 1-frac.y     1 - frac: the weight of the lower texel of each axis
//   in_texel.x in_texel.y where the point lies inside the texel floor(uv * size) that nearest
//                         reads, 0..1 from its lower edge: fract(frac + 0.5)
//   g.x g.y               the fraction shared by every lookup of an N x N kernel (pcf-naive,
//                         pcf-gather, pcf-hw): q = p - (N-1)/2, g = q - floor(q); equals frac
//                         for odd N
//   1-g.x 1-g.y           1 - g: the weight of the footprint's first column / row (times N)
//   tent.s tent.t         the tent filter's own fraction: q = uv * size, s = q + 0.5 - floor(q +
//                         0.5)
//   visibility            the result, 1 = fully lit, 0 = fully shadowed
//   shadow                1 - visibility
//   method                the method's id, e.g. "bilinear2x2" (text)
//   kernel radius         N, and the Poisson disk's radius in texels
//   kernel_sq             N^2: the lookups of an N x N kernel ("{kernel_sq*4}" reads for pcf-naive)
//   rotation              the Poisson disk's rotation in degrees
//   disk_reach            poisson and pcss: how far the farthest of the 16 filter points lies
//                         from the lookup, texels: the scale (radius; pcss: filter_radius) times
//                         1.234, the set's farthest point (0 for the other methods)
//   pcss.search_reach     pcss: the same for the blocker search's points (search_radius * 1.234)
//   map_size              the shadow map's width in texels
//   taps                  texel reads recorded, duplicates kept (pcf-naive 3x3: 36)
//   texels gathers hw_taps  the fetch counts: texel reads, comparison gathers, hardware taps
//   fetches               fetch instructions issued (lookups, gathers, hardware taps, points)
//   distinct              distinct texels read (pcf-naive 3x3: 16)
//   lit_count shadowed_count  reads whose comparison bit is 1 / 0, duplicates kept
//   tap[K].i tap[K].j tap[K].depth tap[K].ref tap[K].margin tap[K].lit tap[K].weight
//                         read K (0-based, in read order): its texel, stored depth, the depth
//                         compared, depth - ref (>= 0 lit, < 0 shadowed), bit, and share of
//                         the result
//   tap[K].shift tap[K].lookup_margin
//                         how far the bias moved read K's own ref from the lookup's ref (its
//                         ref - ref; nonzero under receiver-plane bias), and depth - ref with the
//                         lookup's one ref (what the read would have said without its own ref)
//   dzduv.u dzduv.v       receiver-plane bias: the receiver's d(depth)/d(u, v) the renderer used
//   half_texel_dz.u half_texel_dz.v  the receiver's depth change over half a texel of this map
//                         along u / v: dzduv * 0.5 / map_size
//   light_angle           the angle between the picked point's normal and the direction to the
//                         light, degrees (0: light from straight above, 90: grazing)
//   plane_changed         reads whose bit differs from the one-ref-for-all comparison
//   lookup_shadowed_count reads that would fail against the lookup's one ref
//   fetch[K].value fetch[K].weight fetch[K].u fetch[K].v
//                         fetch instruction K: the value it returned (sum of its reads' weight *
//                         bit over its weight), its weight, where it sampled
//   weight[I,J]           the merged weight of texel (weights.origin.x + I, weights.origin.y + J),
//                         0 for a texel not read
//   weights.origin.x weights.origin.y weights.w weights.h   the merged weight grid's box
//   pixel.x pixel.y       the pixel traced, in the frame rendered (origin top-left)
//   bias cull depth_format  the state's names (text); constant_bias its number
//   origin_shift          how far the map's texel grid is slid, texels (viewer keys O / Shift+O)
//   part[K].visibility    a step with `compare` (the split view, compare_spec.h): part K's
//                         visibility at the same point (0-based, in the order the step names
//                         them), its map rendered with that part's settings
// An index past the trace's reads or fetches (possible only when the state was changed from the
// one the lesson checked) is written "n/a".
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/settings.h"
#include "kernel/trace_explain.h"

namespace pcf {

// What the text may say besides the trace: the state the picture was rendered with.
struct StepContext {
    glm::ivec2 pixel{0, 0};   // the pixel traced, in the frame rendered (origin top-left, y down)
    ShadowSettings settings;  // the filter, the bias and the map the picture was rendered with
    // The angle between the receiver's normal at the picked point and the direction to the
    // light, degrees: 0 the light straight above it, 90 grazing; negative: not known.
    float lightAngleDeg = -1.0f;
    float originShift = 0.0f;  // the map's texel grid slid by this many texels (origin_shift)
    // The step's split view (`compare`): each part's visibility at the point, in its order;
    // empty: not known (part[K] is then "n/a").
    std::vector<float> partVisibility;
};

// Every placeholder name, indexed ones written with K, I and J ("tap[K].depth", "weight[I,J]").
std::vector<std::string> placeholderNames();

struct PlaceholderProblem {
    std::size_t offset;   // where in the text the offending placeholder (or brace) starts
    std::string problem;  // e.g. "unknown placeholder {frac.z}"
};

// The first problem with the placeholders of text, or nullopt: an unknown name, a malformed
// index or number format, an unmatched brace. tapCount, fetchCount and partCount, when not
// negative, are the reads and fetch instructions the step's method issues (fetchCounts) and the
// parts of its `compare`, and weightSize the columns and rows of its merged weights (the trace's
// WeightGrid): a tap[K], fetch[K], part[K] or weight[I,J] past them is a problem too.
std::optional<PlaceholderProblem> checkPlaceholders(std::string_view text, int tapCount = -1,
                                                    int fetchCount = -1, int partCount = -1,
                                                    ivec2 weightSize = ivec2(-1));

// Every problem checkPlaceholders finds, in text order: after each, the text is read on past the
// offending placeholder (or lone brace).
std::vector<PlaceholderProblem> placeholderProblems(std::string_view text, int tapCount = -1,
                                                    int fetchCount = -1, int partCount = -1,
                                                    ivec2 weightSize = ivec2(-1));

// The text with every placeholder replaced by its value for this trace. Throws
// std::invalid_argument on text that checkPlaceholders refuses (lesson files are checked when
// parsed, so that never happens to them).
std::string fillText(std::string_view text, const Trace& trace, const StepContext& ctx);

// The number the placeholder `inside` (what its braces hold: "frac.x", "tap[2].margin",
// "weight[1,1]*9") stands for in this trace; nullopt for a text ({method}) or an index past the
// trace's reads. Throws std::invalid_argument for a placeholder checkPlaceholders refuses, or a
// text one. Claims (lesson_claims.h) compute with it.
std::optional<double> placeholderNumber(std::string_view inside, const Trace& trace,
                                        const StepContext& ctx);
// Whether `inside` names a number placeholder; the reason when not.
std::optional<std::string> numberPlaceholderProblem(std::string_view inside);

// "1 lookups" -> "1 lookup" (and taps, hardware taps, gathers, reads, texels, texel reads,
// fetches, points, samples): the words after a count were written for many. fillText applies it.
std::string singularAfterOne(std::string text);

}  // namespace pcf
