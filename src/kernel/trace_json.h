// trace_json.h: a trace (trace.h) written out: DESIGN.md section 4's JSON object, and the text
// `pcfscope trace` prints.
#pragma once

#include <string>

#include "kernel/trace.h"

namespace pcf {

// DESIGN.md section 4's object, one line of JSON.
std::string traceToJson(const Trace& trace);

// The step-through as a student reads it, with the texel neighbourhood as a table.
std::string traceToText(const Trace& trace);

// s as a JSON string literal, quotes and escapes included.
std::string jsonQuote(const std::string& s);

}  // namespace pcf
