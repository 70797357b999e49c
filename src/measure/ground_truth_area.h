// ground_truth_area.h: the area light's scanline, what ground_truth.cpp integrates over a pixel
// when each point's value is the share of the light's disk it sees (light_visibility.h).
//
// The scanline is cut at the roots of the pixel's outline conics (ground_truth_conics.h: the
// object seen changes only there, and there a box's face gives way to another face), and each
// piece is read at its middle with the exact ray cast: on the centre's object or not, and on
// which of its surfaces (one face of a box, a rectangle's plane, a sphere). Consecutive pieces on
// the same surface form a run; along a run f is integrated by an adaptive trapezoid rule in x
// (panels split where coarse and fine differ most, as over v in ground_truth.h), with every
// point computed on the run's surface in double: the ray through (x, v) meets the surface's
// plane or sphere there (continued past its outline, so a run's ends, on the outline, are read
// exactly; at a sphere's silhouette the ray's closest point to the sphere). lit is that integral,
// its error the panels' 2 |fine - coarse| plus f's own bound times the run's length; a piece
// shorter than UNSURE_PX (ground_truth_rays.h) counts whole into the errors of lit and on, as in
// the hard light's scanline.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "measure/ground_truth_conics.h"
#include "measure/ground_truth_rays.h"
#include "scene/scene.h"

namespace pcf {

struct AreaLine {
    const Scene& scene;
    const CameraRays& rays;
    glm::ivec2 pixel;
    int object;
    double fTarget;                     // the bound each f aims for
    double xTarget;                     // the x-integral's error aimed for, per pixel of length
    const std::vector<Conic>* outline;  // the pixel's conics where the object seen changes
    bool bySlices = false;              // every f by lightVisibleFractionBySlices

    // The scanline at v in [0,1] (window row pixel.y + v).
    Scanline operator()(double v) const;
};

}  // namespace pcf
