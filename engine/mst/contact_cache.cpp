// contact_cache.cpp: the contact matching rule of contact_cache.h.
#include "contact_cache.h"
#include "mdt_bridge.h"

using namespace karma::mst;

namespace {

constexpr int kNone = -1;

// Pass 1 of the rule: equal nonzero features. Returns how many matched.
int MatchByFeature(const McdContact *cc, int n, const MeU32 *oldFeature, int oldCount, int *match, bool *taken) {
  int matched = 0;
  for (int i = 0; i < n; ++i) {
    if (cc[i].feature == 0) continue;
    for (int j = 0; j < oldCount; ++j) {
      if (!taken[j] && oldFeature[j] == cc[i].feature) {
        match[i] = j;
        taken[j] = true;
        ++matched;
        break;
      }
    }
  }
  return matched;
}

// Passes 2 and 3 of the rule: the nearest old contact within reach, where
// one of the two has no identity (pass 2) or whatever their identities
// (pass 3, `renamed`).
void MatchByPosition(const McdContact *cc, int n, MdtContactID *old, const MeU32 *oldFeature, int oldCount,
                     MeReal sign, MeReal reach, bool renamed, int *match, bool *taken) {
  for (int i = 0; i < n; ++i) {
    if (match[i] != kNone) continue;
    int best = kNone;
    MeReal bestD2 = reach * reach;
    for (int j = 0; j < oldCount; ++j) {
      if (taken[j]) continue;
      if (!renamed && cc[i].feature != 0 && oldFeature[j] != 0) continue;
      // Set first: the getters leave them unwritten on a bad contact.
      MeVector3 p = {0, 0, 0}, nrm = {0, 0, 0}, d;
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

// Writes collision contact cc into dynamics contact c (the normal turned to
// body 0's by `sign`).
void Assign(MdtContactID c, const McdContact &cc, MeReal sign, const MdtContactParams &params) {
  const MeVector3 normal = {sign * cc.normal[0], sign * cc.normal[1], sign * cc.normal[2]};
  MdtContactSetFromCollision(c, cc.position, normal, -cc.separation, &params, cc.feature);
}

}  // namespace

namespace karma::mst {

MatchCounts MatchContacts(MdtContactGroupID g, const McdContact *cc, int n, MeReal sign, const MdtContactParams &params,
                          MeReal matchDistance, MstPerContactCBPtr perContact, McdIntersectResult *result) {
  MatchCounts counts;
  MdtContactID old[kContactBuffer];
  MeU32 oldFeature[kContactBuffer];
  bool taken[kContactBuffer] = {};
  int match[kContactBuffer];
  if (n > kContactBuffer) n = kContactBuffer;
  for (int i = 0; i < n; ++i) match[i] = kNone;
  // The group's contacts, in order, at most kContactBuffer of them, and
  // their features (oldFeature[j] is old[j]'s; the matching does not change
  // them).
  const int oldCount = g ? MdtContactGroupGetContacts(g, old, oldFeature, kContactBuffer) : 0;
  // Contacts beyond the buffer (a group filled by hand) are not this
  // step's contacts either.
  if (oldCount == kContactBuffer) {
    while (MdtContactID extra = MdtContactGroupGetNextContact(g, old[kContactBuffer - 1])) {
      MdtContactGroupDestroyContact(g, extra);
      ++counts.removed;
    }
  }
  const int byFeature = MatchByFeature(cc, n, oldFeature, oldCount, match, taken);
  // Passes 2 and 3 match nothing once every new or every old contact is matched.
  if (byFeature < n && byFeature < oldCount) {
    MatchByPosition(cc, n, old, oldFeature, oldCount, sign, matchDistance, false, match, taken);
    MatchByPosition(cc, n, old, oldFeature, oldCount, sign, matchDistance * kRenameFraction, true, match, taken);
  }

  // Unmatched old contacts go first, so the group holds only the kept ones
  // (in their old order) before the new ones are appended.
  for (int j = 0; j < oldCount; ++j) {
    if (taken[j]) continue;
    MdtContactGroupDestroyContact(g, old[j]);
    ++counts.removed;
  }
  bool poolFull = false;
  for (int i = 0; i < n; ++i) {
    MdtContactID c = nullptr;
    if (match[i] != kNone) {
      c = old[match[i]];
      ++counts.kept;
    } else {
      c = poolFull ? nullptr : MdtContactGroupCreateContact(g);
      if (!c) {  // the pool is full (it warned once): this new contact and the later new ones are dropped
        poolFull = true;
        continue;
      }
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
