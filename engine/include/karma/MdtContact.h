/* MdtContact.h: contacts, their parameters, and contact groups.
 *
 * A contact is a constraint at a point between body 0 and body 1 (or the
 * world). Its normal points from body 1 into body 0: the contact pushes body
 * 0 along +normal and body 1 along -normal, never pulls (unless adhesive),
 * and removes a fraction gamma of the penetration depth per step. Contacts
 * can be made by hand (MdtContactCreate, SetBodies, SetPosition, SetNormal,
 * SetPenetration, Enable) or by collision through contact groups.
 *
 * Friction acts in the contact plane along a primary direction (set with
 * MdtContactSetDirection; else last step's primary direction carried onto
 * the new contact plane while the normal has turned less than 60 degrees
 * towards it; else chosen from the normal) and the secondary direction
 * normal x primary. The carried direction is reset with the contact, not by
 * MdtContactClearImpulse.
 *
 * Parameters (MdtContactParams, defaults from Appendix A):
 *   type            FrictionZero | Friction1D (primary only) | Friction2D
 *   model1, model2  Box: |friction force| <= friction1 / friction2 (N);
 *                   NormalForce: <= frictionCoefficient1/2 * normal force
 *   friction1/2     MEINFINITY          frictionCoefficient1/2   0
 *   restitution     0: separating speed after impact = restitution * impact
 *                   speed, for impacts faster than velThreshold (0.001)
 *   softness        0: added to the normal row's diagonal; > 0 lets the
 *                   contact give way (penetrate) like a spring
 *   maxAdhesiveForce 0: the normal force may pull up to this much
 *   slip1/2         0: tangential velocity = slip * friction force
 *                   (force-proportional sliding, for tyres)
 *   slide1/2        0: the velocity of body 0 relative to body 1 that
 *                   friction drives towards (a conveyor belt)
 *   options         bits of MdtContactOption: set by the setters to record
 *                   which features are in use; informational. */
#ifndef KARMA_MDTCONTACT_H
#define KARMA_MDTCONTACT_H
#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN

typedef enum MdtContactType {
  MdtContactTypeFrictionZero = 0,
  MdtContactTypeFriction1D = 1,
  MdtContactTypeFriction2D = 2
} MdtContactType;

typedef enum MdtFrictionModel { MdtFrictionModelBox = 0, MdtFrictionModelNormalForce = 1 } MdtFrictionModel;

typedef enum MdtContactOption {
  MdtContactOptionBounce = 1,
  MdtContactOptionSoft = 2,
  MdtContactOptionAdhesive = 4,
  MdtContactOptionSlip1 = 8,
  MdtContactOptionSlip2 = 16,
  MdtContactOptionSlide1 = 32,
  MdtContactOptionSlide2 = 64
} MdtContactOption;

typedef struct MdtContactParams {
  MdtContactType type;
  MdtFrictionModel model1;
  MdtFrictionModel model2;
  int options;
  MeReal frictionCoefficient1;
  MeReal frictionCoefficient2;
  MeReal restitution;
  MeReal velThreshold;
  MeReal softness;
  MeReal max_adhesive_force;
  MeReal friction1;
  MeReal friction2;
  MeReal slip1;
  MeReal slip2;
  MeReal slide1;
  MeReal slide2;
} MdtContactParams;
typedef MdtContactParams *MdtContactParamsID;

MEPUBLIC void MEAPI MdtContactParamsReset(const MdtContactParamsID p);
MEPUBLIC void MEAPI MdtContactParamsSetType(const MdtContactParamsID p, const MdtContactType t);
MEPUBLIC MdtContactType MEAPI MdtContactParamsGetType(const MdtContactParamsID p);
MEPUBLIC void MEAPI MdtContactParamsSetPrimaryFrictionModel(const MdtContactParamsID p, const MdtFrictionModel m);
MEPUBLIC void MEAPI MdtContactParamsSetSecondaryFrictionModel(const MdtContactParamsID p, const MdtFrictionModel m);
MEPUBLIC MdtFrictionModel MEAPI MdtContactParamsGetPrimaryFrictionModel(const MdtContactParamsID p);
MEPUBLIC MdtFrictionModel MEAPI MdtContactParamsGetSecondaryFrictionModel(const MdtContactParamsID p);
/* Box friction limits (>= 0), both / primary / secondary. */
MEPUBLIC void MEAPI MdtContactParamsSetFriction(const MdtContactParamsID p, const MeReal f);
MEPUBLIC void MEAPI MdtContactParamsSetPrimaryFriction(const MdtContactParamsID p, const MeReal f);
MEPUBLIC void MEAPI MdtContactParamsSetSecondaryFriction(const MdtContactParamsID p, const MeReal f);
MEPUBLIC MeReal MEAPI MdtContactParamsGetPrimaryFriction(const MdtContactParamsID p);
MEPUBLIC MeReal MEAPI MdtContactParamsGetSecondaryFriction(const MdtContactParamsID p);
/* Normal-force friction coefficients (>= 0), both / primary / secondary. */
MEPUBLIC void MEAPI MdtContactParamsSetFrictionCoefficient(const MdtContactParamsID p, const MeReal mu);
MEPUBLIC void MEAPI MdtContactParamsSetPrimaryFrictionCoefficient(const MdtContactParamsID p, const MeReal mu);
MEPUBLIC void MEAPI MdtContactParamsSetSecondaryFrictionCoefficient(const MdtContactParamsID p, const MeReal mu);
MEPUBLIC MeReal MEAPI MdtContactParamsGetPrimaryFrictionCoefficient(const MdtContactParamsID p);
MEPUBLIC MeReal MEAPI MdtContactParamsGetSecondaryFrictionCoefficient(const MdtContactParamsID p);
/* Restitution in [0, 1]; its velocity threshold >= 0. */
MEPUBLIC void MEAPI MdtContactParamsSetRestitution(const MdtContactParamsID p, const MeReal e);
MEPUBLIC MeReal MEAPI MdtContactParamsGetRestitution(const MdtContactParamsID p);
MEPUBLIC void MEAPI MdtContactParamsSetRestitutionThreshold(const MdtContactParamsID p, const MeReal v);
MEPUBLIC MeReal MEAPI MdtContactParamsGetRestitutionThreshold(const MdtContactParamsID p);
MEPUBLIC void MEAPI MdtContactParamsSetSoftness(const MdtContactParamsID p, const MeReal s);
MEPUBLIC MeReal MEAPI MdtContactParamsGetSoftness(const MdtContactParamsID p);
MEPUBLIC void MEAPI MdtContactParamsSetMaxAdhesiveForce(const MdtContactParamsID p, const MeReal f);
MEPUBLIC MeReal MEAPI MdtContactParamsGetMaxAdhesiveForce(const MdtContactParamsID p);
/* Slip (>= 0), both / primary / secondary. */
MEPUBLIC void MEAPI MdtContactParamsSetSlip(const MdtContactParamsID p, const MeReal s);
MEPUBLIC void MEAPI MdtContactParamsSetPrimarySlip(const MdtContactParamsID p, const MeReal s);
MEPUBLIC void MEAPI MdtContactParamsSetSecondarySlip(const MdtContactParamsID p, const MeReal s);
MEPUBLIC MeReal MEAPI MdtContactParamsGetPrimarySlip(const MdtContactParamsID p);
MEPUBLIC MeReal MEAPI MdtContactParamsGetSecondarySlip(const MdtContactParamsID p);
/* Slide (surface velocity), primary / secondary. */
MEPUBLIC void MEAPI MdtContactParamsSetPrimarySlide(const MdtContactParamsID p, const MeReal v);
MEPUBLIC void MEAPI MdtContactParamsSetSecondarySlide(const MdtContactParamsID p, const MeReal v);
MEPUBLIC MeReal MEAPI MdtContactParamsGetPrimarySlide(const MdtContactParamsID p);
MEPUBLIC MeReal MEAPI MdtContactParamsGetSecondarySlide(const MdtContactParamsID p);
MEPUBLIC int MEAPI MdtContactParamsGetOptions(const MdtContactParamsID p);

/* ---- contacts --------------------------------------------------------------
 * Reset: position at body 0's origin, normal (0,1,0), no direction set,
 * penetration 0, parameters reset. Appendix A gives the friction direction
 * (0,1,0), the same as its normal, which is no direction in the contact
 * plane; this library leaves it unset instead (the automatic direction
 * below), the outcome Appendix A's value would have once projected onto the
 * plane, and a contact whose normal is later set elsewhere does not pick up
 * a direction nobody chose (beyond last step's own, carried as above). */
MDT_CONSTRAINT_TYPE_DECL(Contact, MdtContactID)
MDT_CONSTRAINT_COMMON_API(Contact, MdtContactID)
MDT_CONSTRAINT_POSITION_API(Contact, MdtContactID)
#define MdtContactInvalidID ((MdtContactID)0)

/* Normalised; a zero or non-finite normal is rejected. */
MEPUBLIC void MEAPI MdtContactSetNormal(const MdtContactID c, const MeReal x, const MeReal y, const MeReal z);
MEPUBLIC void MEAPI MdtContactGetNormal(const MdtContactID c, MeVector3 normal);
/* The primary friction direction, made orthogonal to the normal. */
MEPUBLIC void MEAPI MdtContactSetDirection(const MdtContactID c, const MeReal x, const MeReal y, const MeReal z);
/* The primary direction in use: the one set, or the automatic one. */
MEPUBLIC void MEAPI MdtContactGetDirection(const MdtContactID c, MeVector3 direction);
MEPUBLIC void MEAPI MdtContactSetPenetration(const MdtContactID c, const MeReal penetration);
MEPUBLIC MeReal MEAPI MdtContactGetPenetration(const MdtContactID c);
MEPUBLIC MdtContactParamsID MEAPI MdtContactGetParams(const MdtContactID c);
/* Copies all parameters at once. */
MEPUBLIC void MEAPI MdtContactSetParams(const MdtContactID c, const MdtContactParamsID p);
/* The chain of contacts of one body pair (used by collision and groups).
 * A group keeps its contacts' chain itself: SetNext on a contact of a group
 * is refused with a warning (use the MdtContactGroup* calls). */
MEPUBLIC MdtContactID MEAPI MdtContactGetNext(const MdtContactID c);
MEPUBLIC void MEAPI MdtContactSetNext(const MdtContactID c, const MdtContactID next);
/* Normal force of the last step (>= 0 unless adhesive). */
MEPUBLIC MeReal MEAPI MdtContactGetNormalForce(const MdtContactID c);

/* ---- contact memory (an extension of this engine; not in Karma 1.2) --------
 * A contact remembers the impulses of its last solve, the normal one and the
 * friction one (as a world vector in its tangent plane), and the next solve
 * starts from them: a collision bridge that keeps a contact alive from step
 * to step (engine/mst/contact_cache.h) warm-starts the solver with it. The
 * feature is the collision's identity for the contact (McdContact::feature),
 * kept for that matching. */
MEPUBLIC void MEAPI MdtContactSetFeature(const MdtContactID c, const MeU32 feature);
MEPUBLIC MeU32 MEAPI MdtContactGetFeature(const MdtContactID c);
/* Last solve's normal impulse (force times step, N s); its friction impulse
 * into `friction` when not NULL. */
MEPUBLIC MeReal MEAPI MdtContactGetImpulse(const MdtContactID c, MeVector3 friction);
/* Forgets the impulses: the next solve starts this contact from zero. */
MEPUBLIC void MEAPI MdtContactClearImpulse(const MdtContactID c);

/* Enabled contacts touching a body (stand-alone or in enabled groups); NULL
 * at the end. The order follows the body's constraints, the most recently
 * enabled first, a group's contacts together in the group's order; enabling
 * or re-binding a constraint of the body changes it. The walk costs the
 * body's constraints, not the world's. The contact passed to Next must be
 * one the walk returned, not removed from its group, regrouped or destroyed
 * since; a contact that does not act on the body ends the walk with a
 * warning. */
MEPUBLIC MdtContactID MEAPI MdtBodyGetFirstContact(const MdtBodyID body);
MEPUBLIC MdtContactID MEAPI MdtBodyGetNextContact(const MdtBodyID body, const MdtContactID c);

/* ---- contact groups ----------------------------------------------------------
 * All the contacts between one pair of bodies (or a body and the world),
 * simulated together when the group is enabled. Contacts created through a
 * group share its bodies and are enabled and disabled with it. */
MDT_CONSTRAINT_TYPE_DECL(ContactGroup, MdtContactGroupID)
MDT_CONSTRAINT_COMMON_API(ContactGroup, MdtContactGroupID)

/* A new contact (default parameters) at the end of the group; NULL with a
 * warning when the world's constraint pool is full. */
MEPUBLIC MdtContactID MEAPI MdtContactGroupCreateContact(const MdtContactGroupID g);
/* Removes a contact from the group and destroys it. */
MEPUBLIC void MEAPI MdtContactGroupDestroyContact(const MdtContactGroupID g, const MdtContactID c);
/* Adds a stand-alone (disabled) contact to the end of the group. It takes
 * the group's bodies, its position and axes keeping their place in the
 * world; so do the group's contacts when the group is given new bodies. */
MEPUBLIC void MEAPI MdtContactGroupAppendContact(const MdtContactGroupID g, const MdtContactID c);
/* Takes a contact out of the group without destroying it (it becomes a
 * disabled stand-alone contact). */
MEPUBLIC void MEAPI MdtContactGroupRemoveContact(const MdtContactGroupID g, const MdtContactID c);
MEPUBLIC MdtContactID MEAPI MdtContactGroupGetFirstContact(const MdtContactGroupID g);
MEPUBLIC MdtContactID MEAPI MdtContactGroupGetNextContact(const MdtContactGroupID g, const MdtContactID c);
MEPUBLIC int MEAPI MdtContactGroupGetCount(const MdtContactGroupID g);
/* The guide's spelling. */
#define MdtContactGrouptGetCount MdtContactGroupGetCount
/* Sum of the normal forces of the group's contacts in the last step. */
MEPUBLIC MeReal MEAPI MdtContactGroupGetNormalForce(const MdtContactGroupID g);

ME_EXTERN_C_END

#endif
