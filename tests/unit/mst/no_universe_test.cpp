// The guide's "Creating a Model Without Using the Universe" (framework,
// space, world and bridge made by hand, a fixed plane with McdModelSetBody
// NULL, a box with a body) stepped with the guide's three calls.
#include "mst_test_support.h"

using namespace mst_test;

TEST(MstWithoutUniverse, TheGuidesHandMadePipeline) {
  McdFrameworkID framework = McdInit(0, 50, 0, 1);
  McdPrimitivesRegisterTypes(framework);
  McdPrimitivesRegisterInteractions(framework);
  McdSpaceID space = McdSpaceAxisSortCreate(framework, McdAllAxes, 50, 100);
  MdtWorldID world = MdtWorldCreate(10, 100, 1, 1);
  MdtWorldSetGravity(world, 0, 0, -kG);
  MstBridgeID bridge = MstBridgeCreate(framework, 2);
  MstSetWorldHandlers(world);

  MeMatrix4 planeTM;
  MeMatrix4TMMakeIdentity(planeTM);
  McdGeometryID planeGeom = McdPlaneCreate(framework);
  McdModelID planeModel = McdModelCreate(planeGeom);
  McdModelSetBody(planeModel, 0);
  McdModelSetTransformPtr(planeModel, planeTM);
  McdSpaceInsertModel(space, planeModel);
  McdSpaceUpdateModel(planeModel);
  McdSpaceFreezeModel(planeModel);

  MdtBodyID boxBody = MdtBodyCreate(world);
  MdtBodyEnable(boxBody);
  MdtBodySetPosition(boxBody, 0, 0, 3);
  McdGeometryID boxGeom = McdBoxCreate(framework, 2, 1, 3);
  MstAutoSetMassProperties(boxBody, boxGeom, 1);
  McdModelID boxModel = McdModelCreate(boxGeom);
  McdModelSetBody(boxModel, boxBody);
  McdSpaceInsertModel(space, boxModel);
  McdSpaceBuild(space);

  for (int i = 0; i < 300; ++i) {
    McdSpaceUpdateAll(space);
    MstBridgeUpdateContacts(bridge, space, world);
    MdtWorldStep(world, kH);
  }
  MeVector3 p;
  MdtBodyGetPosition(boxBody, p);
  EXPECT_NEAR(p[2], 1.5, 1e-3);
  EXPECT_FALSE(MdtBodyIsEnabled(boxBody));        // asleep...
  EXPECT_EQ(McdSpaceModelIsFrozen(boxModel), 1);  // ...and frozen by the handlers

  // Cleaning up as the guide says: remove in a change block (the bridge
  // leaves the space in one), handle the transitions, then destroy.
  McdSpaceRemoveModel(boxModel);
  McdSpaceEndChanges(space);
  McdModelPairContainer *pairs = McdModelPairContainerCreate(8);
  McdSpacePairIterator it;
  McdSpacePairIteratorBegin(space, &it);
  McdModelPairContainerReset(pairs);
  McdSpaceGetTransitions(space, &it, pairs);
  EXPECT_EQ(pairs->goodbyeEnd - pairs->goodbyeFirst, 1);
  EXPECT_NE(pairs->array[0]->responseData, nullptr);  // the resting contact group
  MstHandleTransitions(pairs);
  EXPECT_EQ(pairs->array[0]->responseData, nullptr);
  EXPECT_EQ(MdtWorldGetConstraintCount(world), 0u);
  McdModelPairContainerDestroy(pairs);
  McdSpaceBeginChanges(space);
  McdModelDestroy(boxModel);
  MdtBodyDestroy(boxBody);

  McdSpaceDestroy(space);
  MstBridgeDestroy(bridge);
  MdtWorldDestroy(world);
  McdFrameworkDestroyAllModelsAndGeometries(framework);
  McdTerm(framework);
}
