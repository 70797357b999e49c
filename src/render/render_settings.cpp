#include "render/render_settings.h"

#include <stdexcept>

namespace pcf {

GLenum glTexelFormat(TexelKind kind) {
    switch (kind) {
        case TexelKind::D16:
            return GL_DEPTH_COMPONENT16;
        case TexelKind::D24:
            return GL_DEPTH_COMPONENT24;
        case TexelKind::D32F:
            return GL_DEPTH_COMPONENT32F;
        case TexelKind::Moments2F16:
            return GL_RG16F;
        case TexelKind::Moments2F32:
            return GL_RG32F;
        case TexelKind::Moments4F16:
            return GL_RGBA16F;
        case TexelKind::Moments4F32:
            return GL_RGBA32F;
    }
    throw std::out_of_range("glTexelFormat: unknown texel kind");
}

}  // namespace pcf
