/* McdContact.h: contact points and the result of an intersection test.
 *
 * Conventions (every interaction keeps them; the dispatcher keeps them for
 * the reversed order too):
 *   position    world coordinates, on or between the two surfaces
 *   normal      unit, world frame, pointing FROM model2 TOWARDS model1 of
 *               the pair: moving model1 along +normal separates the two.
 *               This is MdtContact's convention (it pushes body 0 along
 *               +normal), so the bridge copies it with body 0 = model1's.
 *   separation  signed distance along the normal, NEGATIVE when the shapes
 *               overlap (penetration depth = -separation)
 *   dims        the dimension of the touching feature on each model (0
 *               vertex, 1 edge, 2 face): low byte model1, high byte model2
 *   element1/2  which part of model1/model2 made the contact (the child
 *               instance of an aggregate, a triangle of a triangle list...)
 *   feature     the identity of the pair of features (face, edge, vertex of
 *               each shape, and the part of an aggregate or triangle list)
 *               that made the contact: distinct among the contacts of one
 *               intersection, and the same value step after step while the
 *               two shapes keep touching through the same features. 0 means
 *               "no identity": the bridge then matches the contact to the
 *               last step's by position (see engine/mst/contact_cache.h).
 */
#ifndef KARMA_MCDCONTACT_H
#define KARMA_MCDCONTACT_H
#include "MeCall.h"
#include "MePrecision.h"

ME_EXTERN_C_BEGIN

struct McdModelPair;

/* Which part of a model made a contact (a pointer or a small integer). */
typedef union McdContactElement {
  void *ptr;
  int tag;
} McdContactElement;

typedef struct McdContact {
  MeVector3 position;
  MeVector3 normal;
  MeReal separation;
  MeI16 dims;
  MeI16 spare;
  McdContactElement element1;
  McdContactElement element2;
  MeU32 feature;
} McdContact;

/* Filled by McdIntersect. The caller provides `contacts` and
 * `contactMaxCount` (the guide's table also calls it maxContactCount: both
 * names are the same member) and may set `pair`; McdIntersect sets pair,
 * model1/model2 (the pair's, in the pair's order), contactCount (<=
 * contactMaxCount), touch (1 when the shapes touch or overlap) and normal (a
 * representative unit normal of the contact set, same convention as the
 * contacts'; zero when not touching). `data` is free for the interaction. */
typedef struct McdIntersectResult {
  struct McdModelPair *pair;
  struct McdModel *model1;
  struct McdModel *model2;
  McdContact *contacts;
  union {
    int contactMaxCount;
    int maxContactCount;
  };
  int contactCount;
  int touch;
  MeVector3 normal;
  void *data;
} McdIntersectResult;
typedef McdIntersectResult McdInteractionResult; /* the guide uses both names */

ME_EXTERN_C_END
#endif /* KARMA_MCDCONTACT_H */
