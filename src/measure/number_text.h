// number_text.h: a number as pcfscope prints it in the charts (tick labels, notes, subtitles) and
// in the reports that name the same values (stability_report.h). Plain text, no drawing: it lives
// here so that a report and a chart print a value alike, and measure/ needs nothing of charts/.
#pragma once

#include <string>

namespace pcf {

// A number as the charts print it (tick labels, notes, subtitles): %g, or with `percent` the
// share as a percentage ("12.5%").
std::string chartTickText(double v, bool percent = false);

}  // namespace pcf
