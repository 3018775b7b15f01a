// gather.cpp: stage 1 of the step (step.h): the enabled bodies and
// simulated constraints in sort-key order, and the partitions. Only what
// is awake is touched: the bodies come from the awake list and the
// constraints from their lists (active_sets.h).
#include <algorithm>
#include <cmath>

#include "active_sets.h"
#include "step.h"

namespace karma::mdt {

namespace {

bool bodyBefore(const MdtBody *a, const MdtBody *b) {
  if (a->sortKey != b->sortKey) return a->sortKey < b->sortKey;
  return a->serial < b->serial;
}

bool constraintBefore(const MdtConstraint *a, const MdtConstraint *b) {
  if (a->sortKey != b->sortKey) return a->sortKey < b->sortKey;
  return a->serial < b->serial;
}

// A constraint takes part in the step when it is enabled, stands on its own
// (not a contact inside a group) and has at least one enabled body.
bool simulated(const MdtConstraint *c) {
  if (!c->enabled || c->owner || !c->body[0]) return false;
  return c->body[0]->enabled || (c->body[1] && c->body[1]->enabled);
}

// Waking: an enabled constraint between an enabled and a disabled body
// enables the disabled one. Woken bodies join the end of the awake list and
// their constraints are searched in turn, so chains wake through and an
// island wakes as a whole. The bodies woken are the same whatever the
// order; only the order of the enable callbacks follows the list.
// The enable callback may destroy bodies and constraints (MdtWorld.h): the
// walk of b's list goes on from the constraint after c as it was before the
// callback, or from the list's head again when that one has left the list;
// and when b itself has left the awake list, the body that took its place
// there is walked next.
void wakeConnectedSleepers(ActiveSets &a) {
  for (size_t i = 0; i < a.awake.size();) {
    MdtBody *b = a.awake[i];
    MdtConstraint *next = nullptr;
    for (MdtConstraint *c = b->firstConstraint; c; c = next) {
      next = nextAtBody(c, b);
      if (!c->enabled || c->owner || !c->body[0] || !c->body[1]) continue;
      MdtBody *other = c->body[0] == b ? c->body[1] : c->body[0];
      if (other->enabled) continue;
      MdtBodyEnable(other);
      if (next && next->linked[0] != b && next->linked[1] != b) next = b->firstConstraint;
    }
    if (i < a.awake.size() && a.awake[i] == b) ++i;
  }
}

// The enabled bodies and the simulated constraints, each sorted. Every
// simulated constraint is in the list of one of its enabled bodies
// (active_sets.h), so walking the awake bodies' lists finds them all; the
// stamp keeps one joining two awake bodies from being taken twice.
// The awake list is usually in order already: one pass checks it.
void gatherAwake(ActiveSets &a, StepScratch &s) {
  s.bodies.assign(a.awake.begin(), a.awake.end());
  if (!std::is_sorted(s.bodies.begin(), s.bodies.end(), bodyBefore))
    std::sort(s.bodies.begin(), s.bodies.end(), bodyBefore);
  const std::uint64_t stamp = ++a.gatherStamp;
  s.constraints.clear();
  for (MdtBody *b : s.bodies) {
    for (MdtConstraint *c = b->firstConstraint; c; c = nextAtBody(c, b)) {
      if (c->gatherStamp == stamp) continue;
      c->gatherStamp = stamp;
      if (simulated(c)) s.constraints.push_back(c);
    }
  }
  std::sort(s.constraints.begin(), s.constraints.end(), constraintBefore);
}

}  // namespace

void buildPartitions(MdtWorldID world, StepScratch &s) {
  ActiveSets &active = *world->priv->active;
  wakeConnectedSleepers(active);
  gatherAwake(active, s);

  // Adjacency (body index -> constraint indices), in sorted order.
  const int nb = (int)s.bodies.size();
  const int nc = (int)s.constraints.size();
  for (int i = 0; i < nb; ++i) {
    s.bodies[(size_t)i]->index = i;
    s.bodies[(size_t)i]->mark = -1;
  }
  // A constraint's body outside the step (disabled by the enable callback
  // during the wake-up walk, say) acts as the world, as in the assembly:
  // its index is stale, so it is never looked up.
  auto stepped = [&s, nb](const MdtBody *b) {
    return b && b->index >= 0 && b->index < nb && s.bodies[(size_t)b->index] == b;
  };
  s.adjStart.assign((size_t)nb + 1, 0);
  for (MdtConstraint *c : s.constraints) {
    c->mark = -1;
    for (int k = 0; k < 2; ++k)
      if (stepped(c->body[k])) ++s.adjStart[(size_t)c->body[k]->index + 1];
  }
  for (int i = 0; i < nb; ++i) s.adjStart[(size_t)i + 1] += s.adjStart[(size_t)i];
  s.adj.assign((size_t)s.adjStart[(size_t)nb], 0);
  s.adjFill.assign(s.adjStart.begin(), s.adjStart.end() - 1);
  for (int ci = 0; ci < nc; ++ci) {
    MdtConstraint *c = s.constraints[(size_t)ci];
    for (int k = 0; k < 2; ++k)
      if (stepped(c->body[k])) s.adj[(size_t)s.adjFill[(size_t)c->body[k]->index]++] = ci;
  }

  // Breadth-first search from each unvisited body in sorted order. Within a
  // partition, bodies appear in BFS order and constraints in sorted order.
  s.partitions.clear();
  s.partBodies.clear();
  s.partConstraints.clear();
  std::vector<MdtConstraint *> &found = s.found;
  for (int start = 0; start < nb; ++start) {
    MdtBody *seed = s.bodies[(size_t)start];
    if (seed->mark >= 0) continue;
    const int pi = (int)s.partitions.size();
    Partition part{(int)s.partBodies.size(), 0, (int)s.partConstraints.size(), 0};
    found.clear();
    seed->mark = pi;
    s.partBodies.push_back(seed);
    for (size_t q = (size_t)part.bodyStart; q < s.partBodies.size(); ++q) {
      MdtBody *b = s.partBodies[q];
      for (int k = s.adjStart[(size_t)b->index]; k < s.adjStart[(size_t)b->index + 1]; ++k) {
        MdtConstraint *c = s.constraints[(size_t)s.adj[(size_t)k]];
        if (c->mark >= 0) continue;
        c->mark = s.adj[(size_t)k];  // remember its sorted index
        found.push_back(c);
        for (int e = 0; e < 2; ++e) {
          MdtBody *o = c->body[e];
          if (stepped(o) && o->mark < 0) {
            o->mark = pi;
            s.partBodies.push_back(o);
          }
        }
      }
    }
    std::sort(found.begin(), found.end(),
              [](const MdtConstraint *a, const MdtConstraint *b) { return a->mark < b->mark; });
    s.partConstraints.insert(s.partConstraints.end(), found.begin(), found.end());
    part.bodyCount = (int)s.partBodies.size() - part.bodyStart;
    part.constraintCount = (int)s.partConstraints.size() - part.constraintStart;
    s.partitions.push_back(part);
  }
}

}  // namespace karma::mdt
