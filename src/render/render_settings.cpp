#include "render/render_settings.h"

namespace pcf {

GLenum glDepthFormat(DepthFormat format) {
    switch (format) {
        case DepthFormat::D16:
            return GL_DEPTH_COMPONENT16;
        case DepthFormat::D24:
            return GL_DEPTH_COMPONENT24;
        case DepthFormat::D32F:
            return GL_DEPTH_COMPONENT32F;
    }
    return GL_DEPTH_COMPONENT32F;
}

}  // namespace pcf
