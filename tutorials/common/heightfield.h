/* heightfield.h: a regular-grid height field for the tutorials' terrain
 * (QuadBike's "terrain2", CarTerrain), served to collision through a
 * triangle list and drawn through MeViewer.
 *
 * Frame: y up. Grid point (ix, iz) sits at
 *     x = originX + ix * spacing,  z = originZ + iz * spacing,
 *     y = heights[iz * countX + ix],
 * and each cell (ix..ix+1, iz..iz+1) is split along its diagonal from
 * (ix, iz) to (ix+1, iz+1) into two triangles whose normals point up
 * (counter-clockwise seen from above). The surface is exactly these
 * triangles, so HeightFieldHeightAt agrees with what collision sees.
 *
 * The vertices and normals live as long as the field, so the
 * McdUserTriangle records HeightFieldTrianglesNear fills point into them
 * (the triangle list's contract, McdTriangleList.h). The face normal is
 * used. An edge where the surface folds down (a crest) carries its edge
 * flag, so that a wheel on the fold touches the edge where neither face's
 * contact reaches it; flat seams, hollows and the rim carry none (a sphere
 * rolls across them without snagging). */
#ifndef KARMA_TUTORIAL_HEIGHTFIELD_H
#define KARMA_TUTORIAL_HEIGHTFIELD_H

#include "McdTriangleList.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct HeightField {
  int countX, countZ;      /* grid points along x and z (>= 2 each) */
  MeReal spacing;          /* metres between neighbouring grid points */
  MeReal originX, originZ; /* position of grid point (0, 0) */
  MeReal *heights;         /* countX * countZ, index iz * countX + ix */
  MeVector3 *vertices;     /* the grid points, same index */
  MeVector3 *normals;      /* 2 per cell: index 2 * (iz * (countX - 1) + ix) + k */
} HeightField;

/* Grid spacing HeightFieldFromBMP uses, in metres. */
#define HEIGHTFIELD_BMP_SPACING ((MeReal)2)

/* Reads NAME.bmp (8- or 24-bit; grey level, or the mean of R, G and B)
 * found like MeViewer's textures: the working directory, $KARMA_DATA_DIR,
 * the program's directory and its data/, the build tree's share/karma/
 * (where the build writes terrain2.bmp), the installed share/karma/.
 * Pixel (column c, row r) becomes grid point (ix = c, iz = r) with height
 * level / 255 * heightScale; spacing HEIGHTFIELD_BMP_SPACING; the field is
 * centred on x = z = 0. Returns 1, or 0 with a message on stderr (and *hf
 * left empty) when the file is missing or unreadable. */
int HeightFieldFromBMP(HeightField *hf, const char *name, MeReal heightScale);

/* A field from given heights (copied), for tests and generated terrain. */
int HeightFieldCreate(HeightField *hf, int countX, int countZ, MeReal spacing, MeReal originX, MeReal originZ,
                      const MeReal *heights);

/* Frees the arrays; *hf becomes empty. Accepts an empty field. */
void HeightFieldDestroy(HeightField *hf);

/* Height of the triangulated surface at (x, z), clamped to the grid's edge
 * outside it. */
MeReal HeightFieldHeightAt(const HeightField *hf, MeReal x, MeReal z);

/* The grid's bounding box (y from the lowest to the highest point). */
void HeightFieldGetBounds(const HeightField *hf, MeVector3 min, MeVector3 max);

/* Fills up to maxTriangles records with the triangles whose cells overlap
 * the square of half-side `radius` around pos (x, z) and returns how many.
 * When more cells overlap than fit, the ones nearest pos come first. Meant
 * to be called from a triangle list generator (McdTriangleListFnPtr),
 * whose pos and radius it takes as they come. */
int HeightFieldTrianglesNear(const HeightField *hf, const MeVector3 pos, MeReal radius, McdUserTriangle *triangles,
                             int maxTriangles);

#ifdef __cplusplus
}
#endif

#endif
