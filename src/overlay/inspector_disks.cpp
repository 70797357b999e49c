// inspector_disks.cpp: the disks the Poisson points of poisson and pcss lie on, drawn in the
// magnified neighbourhood under the cells' numbers (inspector_plan.h planDisks).
#include "overlay/inspector_plan.h"

namespace pcf::inspector_detail {

DiskRings diskRings(const Trace& tr) {
    const MethodInfo& info = methodInfo(tr.params.method);
    bool pcss = info.searchesBlockers;
    if (!info.hasDisk) return {};
    // poisson: the 16 points scaled by R texels (Jimmy, "Percentage Closer Filtering", 2010).
    // pcss (Fernando, "Percentage-Closer Soft Shadows", 2005): the blocker search's points, then,
    // when the search found a blocker, the filter's, scaled by half the penumbra's width. Each
    // ring is the disk the points fill: the scale times the set's extent, so that every point
    // drawn lies inside its ring.
    float reach = poissonSetReach();
    DiskRings r;
    if (!pcss || tr.pcss.blockers > 0) {
        r.filter = (pcss ? tr.pcss.filterRadius : tr.params.radius) * reach;
    }
    if (pcss) r.search = tr.pcss.searchRadius * reach;
    return r;
}

namespace {

// A ring's stroke as squares along it, one every few pixels, each as wide as the stroke plus a
// pixel a side: the marks the cells' numbers keep clear of.
void ringObstacles(CellMarks& marks, const Rect& area, glm::vec2 centre, float radius,
                   float width) {
    constexpr float STEP_PX = 3.0f;
    int n = std::max(16, static_cast<int>(std::ceil(6.2831853f * radius / STEP_PX)));
    float half = 0.5f * width + 1.0f;
    for (int k = 0; k < n; ++k) {
        float a = 6.2831853f * static_cast<float>(k) / static_cast<float>(n);
        glm::vec2 p = centre + radius * glm::vec2(std::cos(a), std::sin(a));
        Rect r = Rect{p.x - half, p.y - half, 2 * half, 2 * half}.intersect(area);
        if (!r.empty()) marks.rects.push_back(r);
    }
}

}  // namespace

void planDisks(Planner& pl, const Trace& tr, const Rect& area, glm::vec2 point, float cell,
               float width, LegendNeeds& legend, CellMarks& marks) {
    const MethodInfo& info = methodInfo(tr.params.method);
    bool pcss = info.searchesBlockers;
    if (!info.hasDisk) return;
    DiskRings rings = diskRings(tr);
    legend.disk = rings.filter > 0.0f;
    legend.searchDisk = pcss;
    for (float r : {rings.search, rings.filter}) {
        if (r > 0.0f) pl.plan.diskRadii.push_back(r);
    }
    float filter = rings.filter * cell;
    float search = rings.search * cell;
    for (float r : {search, filter}) {
        if (r <= 0.0f) continue;
        ringObstacles(marks, area, point, r, width);
        pl.plan.rings.push_back({point, r, width, area});
    }
    pl.op([=](Canvas& c) {
        c.pushClip(area);
        if (search > 0.0f) c.ring(point, search, width, SEARCH);
        if (filter > 0.0f) c.ring(point, filter, width, ACCENT);
        c.popClip();
    });
}

}  // namespace pcf::inspector_detail
