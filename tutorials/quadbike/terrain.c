/* terrain.c: the ground (the guide's Terrain.c). A collision model without
 * a body: either a flat plane or a triangle list whose triangles come from
 * a height field read from terrain2.bmp, handed out by TriListGeneratorCB
 * only near the model that asks (PASTE_05).
 *
 * The guide chooses between the two with `#if USE_TRI_LIST`; here
 * USE_TRI_LIST (quadbike.h) is the default and landscape.useTriList, set
 * from the command line (-flat, -terrain), chooses at run time. */
#include "quadbike.h"

#include <stdio.h>

Landscape landscape;

/* The most triangles one query may return. */
#define TRILIST_SIZE 50

void InitialiseTerrain(void) {
#if QUADBIKE_STEP >= 5
  /* PASTE_05 */
  if (landscape.useTriList) { /* #if USE_TRI_LIST */
#  define TRI_LIST_SIZE 50
    MeVector3 min = {-10000, -10000, -10000}, max = {10000, 10000, 10000};
    MeALIGNDATA(MeMatrix4, tm, 16) = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    /* The height field: 2 m between grid points, grey levels 0..255
     * become heights 0..15 m */
    if (!HeightFieldFromBMP(&landscape.heightField, "terrain2", 15))
      fprintf(stderr, "quadbike: no terrain2.bmp; the triangle list stays empty\n");
    /* One huge bounding box: the callback decides what is near */
    landscape.collGeom = McdTriangleListCreate(framework, min, max, TRI_LIST_SIZE, TriListGeneratorCB);
    ((McdTriangleList *)landscape.collGeom)->triangleMaxCount = TRILIST_SIZE;
    landscape.collModel = McdModelCreate(landscape.collGeom);
    MeMatrix4Copy(landscape.transform, tm);
  } else {                            /* #else */
    MeALIGNDATA(MeMatrix4, tm, 16) = {/* A plane is the xy plane of its frame: turn it by pi/2 about x so
         * that it lies in xz with its normal up */
                                      {1, 0, 0, 0},
                                      {0, 0, -1, 0},
                                      {0, 1, 0, 0},
                                      {0, 0, 0, 1}};
    landscape.collGeom = McdPlaneCreate(framework);
    landscape.collModel = McdModelCreate(landscape.collGeom);
    MeMatrix4Copy(landscape.transform, tm);
  } /* #endif */
  McdModelSetTransformPtr(landscape.collModel, landscape.transform);
  McdSpaceInsertModel(space, landscape.collModel);
  McdModelSetMaterial(landscape.collModel, groundMat);
  McdSpaceUpdateModel(landscape.collModel);
  McdSpaceFreezeModel(landscape.collModel);
#endif
}

MeReal TerrainHeightAt(MeReal x, MeReal z) {
  if (!landscape.useTriList || !landscape.heightField.heights) return 0;
  return HeightFieldHeightAt(&landscape.heightField, x, z);
}

/* The triangle list's generator: the triangles of the height field's cells
 * under the square of half-side `radius` around the querying model. */
int MEAPI TriListGeneratorCB(McdModelPair *modelPair, McdUserTriangle *triangles, MeVector3 pos, MeReal radius,
                             int maxTriangles) {
  (void)modelPair;
  return HeightFieldTrianglesNear(&landscape.heightField, pos, radius, triangles, maxTriangles);
}
