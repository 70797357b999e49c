// trace_json.h: a trace (trace.h) written out: the JSON object of docs/user-guide.md ("trace"), and
// the text `pcfscope trace` prints.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "kernel/settings.h"
#include "kernel/trace.h"

namespace pcf {

// JSON values are built with nlohmann-json: keys kept in the order written, and numbers held as
// float (the kernel's type), so they print as the shortest decimal that reads back as the same
// float ("0.499", not the double's "0.499000013").
using Json = nlohmann::basic_json<nlohmann::ordered_map, std::vector, std::string, bool,
                                  std::int64_t, std::uint64_t, float>;

// A float as a JSON number: shortest round-trip digits, an integral value as an integer ("1",
// not "1.0"); NaN and infinities as null.
Json jsonNumber(float v);
Json jsonPair(vec2 v);
Json jsonPair(ivec2 v);

// One line, no spaces; bytes that are not UTF-8 become U+FFFD instead of throwing.
std::string jsonDump(const Json& j);

// Which of the parameter table's rows paramsJson writes.
enum class ParamSet {
    All,   // every parameter: the lesson step a frame shows (export's sidecar)
    Raw,   // those render --raw's render.json holds, which `verify` reads back
    Bias,  // the bias mode and its parameters: a trace's `bias`
};

// The settings as one JSON object written from the parameter table (settings.h allParams), so a
// new parameter appears in every sidecar without a line here: each row of `which`, in the
// table's order, under its key (the lesson files' key); numbers as jsonNumber, flags as
// true/false, named values by name ("pcf-gather", "receiver-plane").
Json paramsJson(const ShadowSettings& s, ParamSet which);

// The map as a value (kernel/shadow_map.h MapSpec), as a trace's and render.json's "map":
//   {"size": [w, h], "texels": "32f", "layers": [{"shadow_clip_from_world": [16 numbers,
//    column by column], "depth_range": [near, far], "texel_ws": t}, ...]}
Json mapSpecJson(const MapSpec& map);
// mapSpecJson read back; nullopt with `why` set (a sentence naming the key) when `j` is not one.
std::optional<MapSpec> mapSpecFromJson(const Json& j, std::string& why);

// The trace as that object.
Json traceJson(const Trace& trace);

// traceJson as one line of JSON.
std::string traceToJson(const Trace& trace);

// The step-through as a student reads it, with the texel neighbourhood as a table; for a
// cascaded map, cascadeLine first.
std::string traceToText(const Trace& trace);

// The cascade a lookup read in words: "cascade 2 of 4 (0 nearest): view depths 12.8187 to
// 26.6061, a texel 0.0493 world units wide[, at most 1.2 texels per screen pixel]".
std::string cascadeLine(const TraceCascade& cascade);

}  // namespace pcf
