// contact_cache.cpp: the contact matching rule of contact_cache.h.
#include "contact_cache.h"

using namespace karma::mst;

namespace {

constexpr int kNone = -1;

// The group's contacts, in order, at most kContactBuffer of them.
int CollectOld(MdtContactGroupID g, MdtContactID *old) {
  int n = 0;
  for (MdtContactID c = MdtContactGroupGetFirstContact(g); c && n < kContactBuffer;
       c = MdtContactGroupGetNextContact(g, c))
    old[n++] = c;
  return n;
}

// Pass 1 of the rule: equal nonzero features.
void MatchByFeature(const McdContact *cc, int n, MdtContactID *old, int oldCount, int *match, bool *taken) {
  for (int i = 0; i < n; ++i) {
    if (cc[i].feature == 0) continue;
    for (int j = 0; j < oldCount; ++j) {
      if (!taken[j] && MdtContactGetFeature(old[j]) == cc[i].feature) {
        match[i] = j;
        taken[j] = true;
        break;
      }
    }
  }
}

// Passes 2 and 3 of the rule: the nearest old contact within reach, where
// one of the two has no identity (pass 2) or whatever their identities
// (pass 3, `renamed`).
void MatchByPosition(const McdContact *cc, int n, MdtContactID *old, int oldCount, MeReal sign, MeReal reach,
                     bool renamed, int *match, bool *taken) {
  for (int i = 0; i < n; ++i) {
    if (match[i] != kNone) continue;
    int best = kNone;
    MeReal bestD2 = reach * reach;
    for (int j = 0; j < oldCount; ++j) {
      if (taken[j]) continue;
      if (!renamed && cc[i].feature != 0 && MdtContactGetFeature(old[j]) != 0) continue;
      MeVector3 p, nrm, d;
      MdtContactGetPosition(old[j], p);
      MdtContactGetNormal(old[j], nrm);
      if (sign * MeVector3Dot(nrm, cc[i].normal) < kMatchCosine) continue;
      MeVector3Subtract(d, p, cc[i].position);
      const MeReal d2 = MeVector3Dot(d, d);
      if (d2 < bestD2) {
        bestD2 = d2;
        best = j;
      }
    }
    if (best != kNone) {
      match[i] = best;
      taken[best] = true;
    }
  }
}

// Writes collision contact cc into dynamics contact c.
void Assign(MdtContactID c, const McdContact &cc, MeReal sign, const MdtContactParams &params) {
  MdtContactSetPosition(c, cc.position[0], cc.position[1], cc.position[2]);
  MdtContactSetNormal(c, sign * cc.normal[0], sign * cc.normal[1], sign * cc.normal[2]);
  MdtContactSetPenetration(c, -cc.separation);
  MdtContactSetParams(c, const_cast<MdtContactParams *>(&params));
  MdtContactSetFeature(c, cc.feature);
}

}  // namespace

namespace karma::mst {

MatchCounts MatchContacts(MdtContactGroupID g, const McdContact *cc, int n, MeReal sign, const MdtContactParams &params,
                          MeReal matchDistance, MstPerContactCBPtr perContact, McdIntersectResult *result) {
  MatchCounts counts;
  MdtContactID old[kContactBuffer];
  bool taken[kContactBuffer] = {};
  int match[kContactBuffer];
  if (n > kContactBuffer) n = kContactBuffer;
  for (int i = 0; i < n; ++i) match[i] = kNone;
  const int oldCount = g ? CollectOld(g, old) : 0;
  // Contacts beyond the buffer (a group filled by hand) are not this
  // step's contacts either.
  if (oldCount == kContactBuffer) {
    while (MdtContactID extra = MdtContactGroupGetNextContact(g, old[kContactBuffer - 1])) {
      MdtContactGroupDestroyContact(g, extra);
      ++counts.removed;
    }
  }
  MatchByFeature(cc, n, old, oldCount, match, taken);
  MatchByPosition(cc, n, old, oldCount, sign, matchDistance, false, match, taken);
  MatchByPosition(cc, n, old, oldCount, sign, matchDistance * kRenameFraction, true, match, taken);

  // Unmatched old contacts go first, so the group holds only the kept ones
  // (in their old order) before the new ones are appended.
  for (int j = 0; j < oldCount; ++j) {
    if (taken[j]) continue;
    MdtContactGroupDestroyContact(g, old[j]);
    ++counts.removed;
  }
  for (int i = 0; i < n; ++i) {
    MdtContactID c = nullptr;
    if (match[i] != kNone) {
      c = old[match[i]];
      ++counts.kept;
    } else {
      c = MdtContactGroupCreateContact(g);
      if (!c) break;  // the constraint pool is full (it warned)
      ++counts.created;
    }
    Assign(c, cc[i], sign, params);
    if (perContact && !perContact(result, &result->contacts[i], c)) {
      MdtContactGroupDestroyContact(g, c);
      if (match[i] != kNone) {
        --counts.kept;
        ++counts.removed;
      } else {
        --counts.created;
      }
    }
  }
  return counts;
}

}  // namespace karma::mst
