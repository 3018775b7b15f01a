// gather.cpp: stage 1 of the step (step.h): the enabled bodies and
// simulated constraints in sort-key order, and the partitions.
#include <algorithm>
#include <cmath>

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

}  // namespace

void buildPartitions(MdtWorldID world, StepScratch &s) {
  MdtWorldPrivate *p = world->priv;
  // Waking: an enabled constraint between an enabled and a disabled body
  // enables the disabled one; repeat until nothing changes (chains wake
  // through). Sorted order keeps this deterministic.
  s.constraints.clear();
  for (void *slot = nextConstraintSlot(p, nullptr); slot; slot = nextConstraintSlot(p, slot)) {
    auto *c = static_cast<MdtConstraint *>(slot);
    if (c->enabled && !c->owner && c->body[0] && c->body[1]) s.constraints.push_back(c);
  }
  std::sort(s.constraints.begin(), s.constraints.end(), constraintBefore);
  for (bool changed = true; changed;) {
    changed = false;
    for (MdtConstraint *c : s.constraints) {
      MdtBody *a = c->body[0], *b = c->body[1];
      if (a->enabled != b->enabled) {
        MdtBody *sleeper = a->enabled ? b : a;
        MdtBodyEnable(sleeper);
        changed = true;
      }
    }
  }

  // Gather.
  s.bodies.clear();
  for (void *slot = MePoolGetNextUsed(&p->bodies, nullptr); slot; slot = MePoolGetNextUsed(&p->bodies, slot)) {
    auto *b = static_cast<MdtBody *>(slot);
    if (b->enabled) s.bodies.push_back(b);
  }
  std::sort(s.bodies.begin(), s.bodies.end(), bodyBefore);
  s.constraints.clear();
  for (void *slot = nextConstraintSlot(p, nullptr); slot; slot = nextConstraintSlot(p, slot)) {
    auto *c = static_cast<MdtConstraint *>(slot);
    if (simulated(c)) s.constraints.push_back(c);
  }
  std::sort(s.constraints.begin(), s.constraints.end(), constraintBefore);

  // Adjacency (body index -> constraint indices), in sorted order.
  const int nb = (int)s.bodies.size();
  const int nc = (int)s.constraints.size();
  for (int i = 0; i < nb; ++i) {
    s.bodies[(size_t)i]->index = i;
    s.bodies[(size_t)i]->mark = -1;
  }
  s.adjStart.assign((size_t)nb + 1, 0);
  for (MdtConstraint *c : s.constraints) {
    c->mark = -1;
    for (int k = 0; k < 2; ++k)
      if (c->body[k]) ++s.adjStart[(size_t)c->body[k]->index + 1];
  }
  for (int i = 0; i < nb; ++i) s.adjStart[(size_t)i + 1] += s.adjStart[(size_t)i];
  s.adj.assign((size_t)s.adjStart[(size_t)nb], 0);
  s.adjFill.assign(s.adjStart.begin(), s.adjStart.end() - 1);
  for (int ci = 0; ci < nc; ++ci) {
    MdtConstraint *c = s.constraints[(size_t)ci];
    for (int k = 0; k < 2; ++k)
      if (c->body[k]) s.adj[(size_t)s.adjFill[(size_t)c->body[k]->index]++] = ci;
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
          if (o && o->mark < 0) {
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
