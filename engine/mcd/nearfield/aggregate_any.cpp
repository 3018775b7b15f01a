// aggregate_any.cpp: aggregate (model1) against any type (model2), nested
// aggregates and aggregate-aggregate included.
//
// Each child instance of model1's instance tree is a leaf geometry at its
// composed world TM (relTM, then the parent's TM, cached by
// McdModelUpdate). A child whose cached AABB (grown by the tolerance)
// meets model2's is tested as a stand-in model (a copy of model1 holding
// the child instance) through the interaction table, in whichever order
// the table has; a child that is an aggregate itself recurses the same way
// (an aggregate model2 is split likewise by the mirrored entry). Every
// contact's element1 is the leaf child instance (McdGeometryInstance *)
// that made it. The contacts of all children are merged; when there are
// more than contactMaxCount the deepest are kept. r->normal is the deepest
// contact's normal. Feature id (feature_id.h): Mix(child index + 1, the id
// against the child), made distinct over the merged set.
#include "convex_common.h"
#include "feature_id.h"

#include <algorithm>
#include <utility>
#include <vector>

using namespace karma::mcd;

namespace karma::mcd {

int DispatchPair(McdModelPair *pair, McdIntersectResult *r) {
  McdFramework *fw = pair->model1->framework;
  const McdInteractions *e = McdFrameworkGetInteraction(fw, McdGeometryGetTypeId(pair->model1->instance.geometry),
                                                        McdGeometryGetTypeId(pair->model2->instance.geometry));
  r->contactCount = 0;
  r->touch = 0;
  MeVector3Set(r->normal, 0, 0, 0);
  if (!e) return 0;
  if (e->swap) std::swap(pair->model1, pair->model2);
  r->model1 = pair->model1, r->model2 = pair->model2;
  e->intersectFn(pair, r);
  if (e->swap) std::swap(pair->model1, pair->model2);
  r->model1 = pair->model1, r->model2 = pair->model2;
  r->contactCount = std::clamp(r->contactCount, 0, r->contactMaxCount);
  if (e->swap) {
    for (int i = 0; i < r->contactCount; ++i) {
      McdContact &c = r->contacts[i];
      MeVector3Negate(c.normal);
      std::swap(c.element1, c.element2);
      const unsigned d = (unsigned)(unsigned short)c.dims;
      c.dims = (MeI16)(((d & 0xFFu) << 8) | (d >> 8));
    }
    MeVector3Negate(r->normal);
  }
  return r->touch;
}

}  // namespace karma::mcd

namespace {

bool Overlap(const McdGeometryInstance &a, const McdGeometryInstance &b, MeReal tol) {
  for (int k = 0; k < 3; ++k)
    if (a.aabbMax[k] + tol < b.aabbMin[k] || b.aabbMax[k] + tol < a.aabbMin[k]) return false;
  return true;
}

int MEAPI Intersect(McdModelPair *p, McdIntersectResult *r) {
  const McdModel *agg = p->model1;
  const McdGeometryInstance &top = agg->instance;
  const MeReal tol = ContactTolerance(agg->framework);
  const int room = std::max(r->contactMaxCount, 1);
  std::vector<McdContact> merged, scratch((std::size_t)std::max(room, 16));
  int touch = 0;
  for (int i = 0; i < top.childCount; ++i) {
    const McdGeometryInstance *child = top.children[i];
    if (!Overlap(*child, p->model2->instance, tol)) continue;
    McdModel stand = *agg;  // the child as a model of its own
    stand.instance = *child;
    McdModelPair sub = *p;
    sub.model1 = &stand;
    sub.m_cachedData = nullptr;
    sub.m_contactMemory = nullptr;
    McdIntersectResult sr{};
    sr.pair = p;
    sr.contacts = scratch.data();
    sr.contactMaxCount = (int)scratch.size();
    if (!DispatchPair(&sub, &sr)) continue;
    touch = 1;
    const bool leaf = child->childCount == 0;
    for (int k = 0; k < sr.contactCount; ++k) {
      if (leaf) scratch[k].element1.ptr = const_cast<McdGeometryInstance *>(child);
      scratch[k].feature = feature::Mix((MeU32)i + 1, scratch[k].feature);
      merged.push_back(scratch[k]);
    }
  }
  if (!touch) return 0;
  std::stable_sort(merged.begin(), merged.end(),
                   [](const McdContact &a, const McdContact &b) { return a.separation < b.separation; });
  const int n = std::min((int)merged.size(), r->contactMaxCount);
  const int first = r->contactCount;
  for (int k = 0; k < n; ++k) r->contacts[r->contactCount++] = merged[k];
  feature::MakeDistinct(r->contacts, first, r->contactCount);
  if (!merged.empty()) MeVector3Copy(r->normal, merged[0].normal);
  r->touch = 1;
  return 1;
}

}  // namespace

extern "C" void MEAPI McdAggregateRegisterInteractions(McdFrameworkID fw) {
  McdInteractions fns{};
  fns.intersectFn = Intersect;
  for (int t = 0; t < kMcdGeometryBuiltInTypes; ++t) RegisterInteractionQuietly(fw, kMcdGeometryTypeAggregate, t, fns);
}
