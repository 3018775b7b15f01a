// contact_group.cpp: contact groups -- every contact between one pair of
// bodies, stepped as one constraint. The group's rows are its contacts'
// rows in list order (contact.cpp).
//
// A contact of a group has the group's bodies: MdtConstraintSetBodies on the
// group (attach) and MdtContactGroupAppendContact give them to it, keeping
// its attachment's place in the world (moveToBodies), MdtBodyDestroy takes
// them from both, and MdtConstraintSetBodies refuses a contact of a group.
// The group's list and count change only here (MdtContactSetNext refuses a
// contact of a group).
#include <algorithm>

#include "contact_internal.h"

using namespace karma::mdt;

namespace {

void reset(MdtConstraint *c) {
  auto *g = as<MdtContactGroup>(c);
  g->normalForce = 0;
  // Contacts stay in the group; their parameters are reset.
  for (MdtContact *k = g->first; k; k = k->next) resetContact(k);
}

void syncBodies(MdtContactGroup *g, MdtContact *k) {
  k->body[0] = g->body[0];
  k->body[1] = g->body[1];
}

// The group has new bodies: its contacts move to them.
void attach(MdtConstraint *c) {
  auto *g = as<MdtContactGroup>(c);
  for (MdtContact *k = g->first; k; k = k->next) moveToBodies(k, g->body[0], g->body[1]);
}

void addRows(MdtConstraint *c, RowSink &sink, const StepContext &ctx) {
  auto *g = as<MdtContactGroup>(c);
  MeVector3 origin[2];
  for (int i = 0; i < 2; ++i) bodyOrigin(g, i, origin[i]);
  for (MdtContact *k = g->first; k; k = k->next) {
    syncBodies(g, k);
    addContactRows(k, sink, ctx, origin);
  }
}

int rowCapacity(const MdtConstraint *c) { return 3 * as<MdtContactGroup>(c)->count; }

void afterSolve(MdtConstraint *c, const Row *rows, const MeReal *impulse, int n, const StepContext &ctx) {
  auto *g = as<MdtContactGroup>(c);
  g->normalForce = 0;
  // Walk the rows as addContactRows wrote them: a normal row, then one row
  // per friction direction that acts (roles are not kept here, so recount
  // from the params: contactRowCount).
  int r = 0;
  for (MdtContact *k = g->first; k && r < n; k = k->next) {
    k->normalForce = impulse[r] * ctx.invH;
    g->normalForce += k->normalForce;
    r += storeContactImpulses(k, rows + r, impulse + r, n - r);
  }
}

// The lines of each hinted contact (MdtContactGroup::hint) that the bridge,
// addContactRows and storeContactImpulses read or write: the base's first
// (type, bodies, attachment), the params, and the line from the normal to
// the warm memory (contact_internal.h); in double precision those fields
// take two more lines.
void prefetch(const MdtConstraint *c) {
  const auto *g = static_cast<const MdtContactGroup *>(c);
  const int n = std::min(g->count, kContactHints);
  for (int j = 0; j < n; ++j) {
    const MdtContact *k = g->hint[j];
    __builtin_prefetch(k);
    __builtin_prefetch(&k->params);
    __builtin_prefetch(&k->normal);
    if constexpr (sizeof(MeReal) > 4) {
      __builtin_prefetch(&k->next);
      __builtin_prefetch(&k->warmFriction[2]);
    }
  }
}

void destroy(MdtConstraint *c) {
  auto *g = as<MdtContactGroup>(c);
  MdtContact *k = g->first;
  g->first = nullptr;
  g->count = 0;
  while (k) {
    MdtContact *next = k->next;
    k->owner = nullptr;
    releaseConstraintSlot(c->world->priv, k);
    k = next;
  }
}

}  // namespace

namespace karma::mdt {

void refreshContactHints(MdtContactGroup *g) {
  int j = 0;
  for (MdtContact *k = g->first; k && j < kContactHints; k = k->next) g->hint[j++] = k;
}

extern const ConstraintType kContactGroupType = {MdtConstraintTypeContactGroup,
                                                 "ContactGroup",
                                                 sizeof(MdtContactGroup),
                                                 0,
                                                 rowCapacity,
                                                 reset,
                                                 addRows,
                                                 afterSolve,
                                                 destroy,
                                                 attach,
                                                 prefetch};
}  // namespace karma::mdt

MDT_DEFINE_CONSTRAINT_TYPE(ContactGroup, kContactGroupType)

extern "C" {

void MEAPI MdtContactGroupAppendContact(const MdtContactGroupID g, const MdtContactID c) {
  static const char *fn = "MdtContactGroupAppendContact";
  if (!checkType(g, kContactGroupType, fn) || !checkType(c, kContactType, fn)) return;
  ME_REQUIRE_ARG(c->owner == nullptr, fn, "the contact already belongs to a group; ignored");
  ME_REQUIRE_ARG(c->world == g->world, fn, "the contact belongs to another world; ignored");
  c->enabled = FALSE;
  c->owner = g;
  c->next = nullptr;
  moveToBodies(c, g->body[0], g->body[1]);
  MdtContact **tail = &g->first;
  while (*tail) tail = &(*tail)->next;
  *tail = c;
  if (g->count < kContactHints) g->hint[g->count] = c;
  ++g->count;
  g->warmRows = 0;
}

MdtContactID MEAPI MdtContactGroupCreateContact(const MdtContactGroupID g) {
  if (!checkType(g, kContactGroupType, "MdtContactGroupCreateContact")) return nullptr;
  MdtContactID c = MdtContactCreate(g->world);
  if (!c) return nullptr;
  if (g->body[0]) {
    c->body[0] = g->body[0];
    c->body[1] = g->body[1];
    attachDefault(c);
  }
  MdtContactGroupAppendContact(g, c);
  return c;
}

void MEAPI MdtContactGroupRemoveContact(const MdtContactGroupID g, const MdtContactID c) {
  static const char *fn = "MdtContactGroupRemoveContact";
  if (!checkType(g, kContactGroupType, fn) || !checkType(c, kContactType, fn)) return;
  ME_REQUIRE_ARG(c->owner == g, fn, "the contact is not in this group; ignored");
  for (MdtContact **link = &g->first; *link; link = &(*link)->next) {
    if (*link == c) {
      *link = c->next;
      --g->count;
      break;
    }
  }
  c->next = nullptr;
  c->owner = nullptr;
  c->enabled = FALSE;
  g->warmRows = 0;
  refreshContactHints(g);  // the walk above has just read the links it follows
}

void MEAPI MdtContactGroupDestroyContact(const MdtContactGroupID g, const MdtContactID c) {
  static const char *fn = "MdtContactGroupDestroyContact";
  if (!checkType(g, kContactGroupType, fn) || !checkType(c, kContactType, fn)) return;
  ME_REQUIRE_ARG(c->owner == g, fn, "the contact is not in this group; ignored");
  MdtContactGroupRemoveContact(g, c);
  MdtConstraintDestroy(c);
}

MdtContactID MEAPI MdtContactGroupGetFirstContact(const MdtContactGroupID g) {
  if (!checkType(g, kContactGroupType, "MdtContactGroupGetFirstContact")) return nullptr;
  return g->first;
}

MdtContactID MEAPI MdtContactGroupGetNextContact(const MdtContactGroupID g, const MdtContactID c) {
  static const char *fn = "MdtContactGroupGetNextContact";
  if (!checkType(g, kContactGroupType, fn) || !checkType(c, kContactType, fn)) return nullptr;
  ME_REQUIRE_ARG_RET(c->owner == g, nullptr, fn, "the contact is not in this group");
  return c->next;
}

int MEAPI MdtContactGroupGetCount(const MdtContactGroupID g) {
  if (!checkType(g, kContactGroupType, "MdtContactGroupGetCount")) return 0;
  return g->count;
}

int MEAPI MdtContactGroupGetContacts(const MdtContactGroupID g, MdtContactID *contacts, MeU32 *features, int max) {
  if (!checkType(g, kContactGroupType, "MdtContactGroupGetContacts")) return 0;
  int n = 0;
  for (MdtContact *k = g->first; k && n < max; k = k->next, ++n) {
    contacts[n] = k;
    features[n] = k->feature;
  }
  return n;
}

// Under link-time optimisation this is inlined into the bridge's loop; were
// it not, GCC could take a function that only prefetches for one without
// effects and drop its calls, as it did a first version of the bridge's
// own prefetch (docs/NOTES.md, "String instructions in hot loops").
void MEAPI MdtContactGroupPrefetch(const MdtContactGroupID g) {
  if (!g) return;
  __builtin_prefetch(g);
  __builtin_prefetch(&g->hint[0]);
  __builtin_prefetch(&g->hint[kContactHints - 1]);  // the array may straddle two lines
}

void MEAPI MdtContactGroupPrefetchContacts(const MdtContactGroupID g) {
  if (g && g->type == &kContactGroupType) prefetch(g);
}

MeReal MEAPI MdtContactGroupGetNormalForce(const MdtContactGroupID g) {
  if (!checkType(g, kContactGroupType, "MdtContactGroupGetNormalForce")) return 0;
  return g->normalForce;
}

}  // extern "C"
