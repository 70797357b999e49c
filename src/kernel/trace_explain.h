// trace_explain.h: a recorded lookup (trace.h) put into words, step by step, for a student.
// Only reads the record: every number it prints is one the kernel computed.
#pragma once

#include <string>
#include <vector>

#include "kernel/trace.h"

namespace pcf {

// The steps that explain `trace` (its params, taps, fetches, weights and results), in order;
// the last states the visibility (TraceStepKind::Result; box2x2's AverageBits).
std::vector<TraceStep> explainTrace(const Trace& trace);

// A step kind's heading as the inspector and `pcfscope trace` print it.
const char* stepTitle(TraceStepKind kind);

// A step kind's stable id for JSON ("project", "lerp", "result", ...).
const char* stepKindName(TraceStepKind kind);

// A number as the steps print it: up to 4 decimals, trailing zeros trimmed ("0.8", "0.0711").
std::string formatNumber(float value);
// A position "(u, v)" of two such numbers.
std::string formatPair(vec2 value);
// A comparison's result: the bit "0" or "1", or the soft comparison's fraction.
std::string formatBit(float lit);

}  // namespace pcf
