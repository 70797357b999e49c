#include "measure/number_text.h"

#include <cmath>
#include <cstdio>

namespace pcf {

std::string chartTickText(double v, bool percent) {
    char buf[32];
    if (percent) {
        std::snprintf(buf, sizeof buf, "%g%%", std::round(v * 1e4) / 1e2);
    } else {
        std::snprintf(buf, sizeof buf, "%g", v);
    }
    return buf;
}

}  // namespace pcf
