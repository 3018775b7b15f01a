#include "render.h"

#include <stb_image_write.h>

#include <math.h>
#include <stdlib.h>

#define TRAIL_EVERY 4 /* frames between trail dots */

typedef struct {
  int x, y;
} Pixel;

struct DemoRenderer {
  int width, height;
  MeReal scale;  /* pixels per metre */
  MeReal xMin;   /* world x at pixel column 0 */
  int groundRow; /* pixel row of y = 0 */
  unsigned char *rgb;
  int trailCapacity;
  int trailLength[DEMO_BALL_COUNT];
  Pixel *trail[DEMO_BALL_COUNT];
};

/* Round half up; exact for the coordinates we meet (|v| far below 2^29). */
static int Round(MeReal v) { return (int)floor((double)v + 0.5); }

static Pixel ToPixel(const DemoRenderer *r, const MeReal *p) {
  Pixel px;
  px.x = Round((p[0] - r->xMin) * r->scale);
  px.y = r->groundRow - Round(p[1] * r->scale);
  return px;
}

DemoRenderer *DemoRendererCreate(int width, int height, int frameCount) {
  int i;
  DemoRenderer *r = (DemoRenderer *)calloc(1, sizeof *r);
  if (!r) return NULL;
  r->width = width;
  r->height = height;
  r->xMin = (MeReal)-0.2;
  r->scale = (MeReal)width / (MeReal)10.4;
  r->groundRow = height - 1 - height / 8;
  r->rgb = (unsigned char *)malloc((size_t)width * (size_t)height * 3);
  r->trailCapacity = frameCount / TRAIL_EVERY + 1;
  for (i = 0; i < DEMO_BALL_COUNT; ++i) {
    r->trail[i] = (Pixel *)malloc((size_t)r->trailCapacity * sizeof(Pixel));
    if (!r->trail[i]) break;
  }
  if (!r->rgb || i < DEMO_BALL_COUNT) {
    DemoRendererDestroy(r);
    return NULL;
  }
  return r;
}

void DemoRendererDestroy(DemoRenderer *r) {
  int i;
  if (!r) return;
  for (i = 0; i < DEMO_BALL_COUNT; ++i) free(r->trail[i]);
  free(r->rgb);
  free(r);
}

void DemoRendererRecord(DemoRenderer *r, const DemoWorld *world, int frame) {
  int i;
  if (frame % TRAIL_EVERY != 0) return;
  for (i = 0; i < DEMO_BALL_COUNT; ++i)
    if (r->trailLength[i] < r->trailCapacity) r->trail[i][r->trailLength[i]++] = ToPixel(r, world->balls[i].position);
}

static void Put(DemoRenderer *r, int x, int y, int red, int green, int blue) {
  unsigned char *p;
  if (x < 0 || y < 0 || x >= r->width || y >= r->height) return;
  p = r->rgb + ((size_t)y * (size_t)r->width + (size_t)x) * 3;
  p[0] = (unsigned char)red, p[1] = (unsigned char)green, p[2] = (unsigned char)blue;
}

static void DrawBackground(DemoRenderer *r) {
  int x, y;
  for (y = 0; y < r->height; ++y) {
    for (x = 0; x < r->width; ++x) {
      if (y < r->groundRow) /* sky: lighter towards the horizon */
        Put(r, x, y, 120 + 100 * y / r->groundRow, 170 + 70 * y / r->groundRow, 235);
      else if (y <= r->groundRow + 1) /* ground line */
        Put(r, x, y, 60, 45, 30);
      else
        Put(r, x, y, 130, 105, 70);
    }
  }
}

/* Bresenham's line, both ends included. */
static void DrawLine(DemoRenderer *r, Pixel a, Pixel b, int red, int green, int blue) {
  const int dx = abs(b.x - a.x), sx = a.x < b.x ? 1 : -1;
  const int dy = -abs(b.y - a.y), sy = a.y < b.y ? 1 : -1;
  int err = dx + dy;
  for (;;) {
    int e2;
    Put(r, a.x, a.y, red, green, blue);
    if (a.x == b.x && a.y == b.y) break;
    e2 = 2 * err;
    if (e2 >= dy) err += dy, a.x += sx;
    if (e2 <= dx) err += dx, a.y += sy;
  }
}

static void DrawBall(DemoRenderer *r, const DemoBall *b) {
  const Pixel c = ToPixel(r, b->position);
  const int radius = Round(b->radius * r->scale) > 1 ? Round(b->radius * r->scale) : 1;
  const int inner = radius > 2 ? radius - 2 : 0;
  const MeReal *q = b->quaternion;
  MeReal axis[3];
  Pixel tip;
  int dx, dy;
  for (dy = -radius; dy <= radius; ++dy) {
    for (dx = -radius; dx <= radius; ++dx) {
      const int d2 = dx * dx + dy * dy;
      if (d2 > radius * radius + radius) continue; /* +radius: rounder small discs */
      if (d2 > inner * inner + inner)
        Put(r, c.x + dx, c.y + dy, b->colour[0] / 2, b->colour[1] / 2, b->colour[2] / 2);
      else
        Put(r, c.x + dx, c.y + dy, b->colour[0], b->colour[1], b->colour[2]);
    }
  }
  /* The body x axis in the world: the first column of the rotation of q. */
  axis[0] = 1 - 2 * (q[2] * q[2] + q[3] * q[3]);
  axis[1] = 2 * (q[1] * q[2] + q[0] * q[3]);
  axis[2] = 2 * (q[1] * q[3] - q[0] * q[2]);
  tip.x = c.x + Round(axis[0] * (MeReal)inner);
  tip.y = c.y - Round(axis[1] * (MeReal)inner);
  (void)axis[2]; /* the side view does not show depth */
  DrawLine(r, c, tip, 255, 255, 255);
}

int DemoRendererWritePng(DemoRenderer *r, const DemoWorld *world, int frame, int frameCount, const char *path) {
  int i, j;
  DrawBackground(r);
  for (i = 0; i < DEMO_BALL_COUNT; ++i) {
    const unsigned char *c = world->balls[i].colour;
    for (j = 0; j < r->trailLength[i]; ++j)
      Put(r, r->trail[i][j].x, r->trail[i][j].y, (c[0] + 255) / 2, (c[1] + 255) / 2, (c[2] + 255) / 2);
  }
  for (i = 0; i < DEMO_BALL_COUNT; ++i) DrawBall(r, &world->balls[i]);
  /* Progress bar: how far through the run this frame is. */
  {
    const int filled = frameCount > 1 ? (int)((long)(r->width - 1) * frame / (frameCount - 1)) : r->width - 1;
    for (i = 0; i <= filled; ++i) Put(r, i, 0, 40, 40, 40), Put(r, i, 1, 40, 40, 40);
  }
  return stbi_write_png(path, r->width, r->height, 3, r->rgb, r->width * 3) != 0;
}
