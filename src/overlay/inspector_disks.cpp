// inspector_disks.cpp: the disks the Poisson points of poisson and pcss lie on, drawn in the
// magnified neighbourhood under the cells' numbers (inspector_plan.h planDisks).
#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

void planDisks(Planner& pl, const Trace& tr, const Rect& area, glm::vec2 point, float cell,
               float width, LegendNeeds& legend) {
    bool pcss = tr.params.method == PCF_PCSS;
    if (tr.params.method != PCF_POISSON && !pcss) return;
    // poisson: the disk of radius R texels (Jimmy, "Percentage Closer Filtering", 2010).
    // pcss (Fernando, "Percentage-Closer Soft Shadows", 2005): the blocker search's disk, then,
    // when the search found a blocker, the filter's disk of half the penumbra's width.
    legend.disk = !pcss || tr.pcss.blockers > 0;
    legend.searchDisk = pcss;
    float filter = legend.disk ? (pcss ? tr.pcss.filterRadius : tr.params.radius) * cell : 0.0f;
    float search = pcss ? tr.pcss.searchRadius * cell : 0.0f;
    pl.op([=](Canvas& c) {
        c.pushClip(area);
        if (search > 0.0f) c.ring(point, search, width, SEARCH);
        if (filter > 0.0f) c.ring(point, filter, width, ACCENT);
        c.popClip();
    });
}

}  // namespace pcf::inspector_detail
