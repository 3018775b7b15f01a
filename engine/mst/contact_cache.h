// contact_cache.h: contacts with memory. Each step the bridge hands this
// step's collision contacts of one pair to MatchContacts, which updates the
// pair's contact group in place so that a contact the collision reports
// again keeps its MdtContact, and with it last step's impulses (normal and
// friction, see MdtContactGetImpulse), which warm-start the solver.
//
// =============================================================================
// THE CONTACT MATCHING RULE
// =============================================================================
// Old contacts: the group's contacts, in the group's order. New contacts:
// this step's collision contacts of the pair, in the nearfield's order.
//   1. By feature. A new contact with a nonzero feature identity
//      (McdContact::feature) takes the old contact with the same identity.
//      Identities are distinct within one intersection, so this is exact.
//   2. By position. A new contact still unmatched takes the nearest old
//      contact still unmatched for which at least one of the two has no
//      identity (feature 0: contacts whose shapes cannot name their
//      features), provided they are closer than kMatchDistance (times the
//      framework's length scale) and their normals differ by less than
//      the angle of kMatchCosine.
//   3. Renamed. A new contact still unmatched takes the nearest old contact
//      still unmatched within kRenameFraction * kMatchDistance (and within
//      the angle of kMatchCosine), whatever their identities: the same point named
//      through another feature. Where two aligned boxes' corners coincide,
//      rounding decides from step to step which box's vertex names the
//      corner; without this pass the contact would be re-made, losing its
//      impulses and its place. Two different identities farther apart
//      never match.
//   4. A matched old contact takes the new contact's position, normal,
//      penetration, feature and the material's parameters, and keeps its
//      place in the group, its impulses and its friction axis. An old contact left unmatched
//      is destroyed. A new contact left unmatched becomes a new MdtContact,
//      with zero impulses, appended to the group in the nearfield's order.
// So the group's order is stable: contacts that persist keep their
// relative order, new ones come last. Everything depends only on the two
// lists, never on memory addresses: the result is deterministic.
// =============================================================================
#pragma once

#include "mst_internal.h"

namespace karma::mst {

// Farthest two contacts may be apart to match by position, in units of the
// framework's length scale.
inline constexpr MeReal kMatchDistance = (MeReal)0.05;
// Fraction of kMatchDistance within which contacts of different identities
// are the same point renamed (pass 3).
inline constexpr MeReal kRenameFraction = (MeReal)0.04;
// Cosine of the largest angle between two normals that may match.
inline constexpr MeReal kMatchCosine = (MeReal)0.9;

// What the matching did, for the caller's bookkeeping and for tests.
struct MatchCounts {
  int kept = 0;     // old contacts matched and updated
  int created = 0;  // new contacts appended
  int removed = 0;  // old contacts destroyed
};

// Brings group g (body 0's normals: `sign` flips the collision normals when
// the pair's model1 has no body) to this step's contacts `cc` (count n),
// with the parameters `params`. `matchDistance` is kMatchDistance already
// scaled to the world. Calls `perContact` for every contact made or kept
// (it may reject one: the contact is destroyed). Never allocates beyond the
// world's constraint pool; a full pool drops the new contacts it has no
// room for (the pool warned), while every kept contact is still updated.
MatchCounts MatchContacts(MdtContactGroupID g, const McdContact *cc, int n, MeReal sign, const MdtContactParams &params,
                          MeReal matchDistance, MstPerContactCBPtr perContact, McdIntersectResult *result);

}  // namespace karma::mst
