// mst_internal.h: the bridge's private layout (not installed).
//
// The material table is symmetric: entry (a, b) and (b, a) are the one
// record at Entry(min, max). A bridge owns the pair container its
// MstBridgeUpdateContacts loop fills and the collision contact buffer
// McdIntersect writes into.
#pragma once

#include "Mst.h"

namespace karma::mst {

struct MaterialEntry {
  MdtContactParams params;
  MstIntersectCBPtr intersectCB;
  MstPerContactCBPtr perContactCB;
  MstPerPairCBPtr perPairCB;
};

inline constexpr int kPairChunk = 128;     // pairs per McdSpaceGetPairs call
inline constexpr int kContactBuffer = 64;  // collision contacts per pair and step

}  // namespace karma::mst

struct MstBridge {
  McdFrameworkID framework;
  int maxMaterials;
  int materialCount;                     // materials in use, >= 1
  karma::mst::MaterialEntry *materials;  // maxMaterials^2, MeMemoryAPI
  McdModelPairContainer *pairs;
  McdContact contacts[karma::mst::kContactBuffer];
};

namespace karma::mst {

// The entry of two materials in use, else a warning naming fn and NULL.
MaterialEntry *Entry(MstBridge *b, MstMaterialID m1, MstMaterialID m2, const char *fn);
// Removes a model from its space, first destroying the contact groups of
// its pairs and saying McdGoodbye to them, so the goodbyes that follow no
// longer need the model or its body. Warns (naming fn) outside a block.
bool RemoveModelAndItsContacts(McdModelID model, const char *fn);
// Destroys the pair's contact group (pair->responseData), if it has one.
void DropContactGroup(McdModelPair *pair);
// Destroys the contact groups of a model's pairs (the pairs stay), when its
// space is in a change block (between steps: no collision step holds a
// group then). A pair of frozen models is not collided, so the collision
// step's own check of a group's bodies (collisions.cpp) would not reach it.
void DropModelContactGroups(McdModelID model);
// Before a universe step of size h: each model in the universe's space
// inherits its body's sort key and gets its bounds padding for the step
// (the rules are in step_bounds.cpp).
void PrepareModelsForStep(MstUniverseID u, MeReal h);

}  // namespace karma::mst
