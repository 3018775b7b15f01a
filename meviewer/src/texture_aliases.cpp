/* texture_aliases.cpp: the guide's older names of the texture calls
 * (MeViewer.h), each the same function as its current name. */
#include "MeViewer.h"

extern "C" {

int MEAPI RCreateTextureID(RRender *rc, char *filename) { return RRenderTextureCreate(rc, filename); }

int MEAPI RSetTexture(RRender *rc, RGraphic *rg, char *filename) { return RGraphicSetTexture(rc, rg, filename); }

}  // extern "C"
