// Scene rendering (mjr_render) and 2D drawing (mjr_text, mjr_overlay, mjr_label,
// mjr_rectangle) under OSMesa, printed as hashes of the pixels and depth read back, for
// comparison against 2.2.2.
//   render_scene MODEL...        per model, at a state after 40 steps: every rendering flag,
//                                visual flags and labels, transparency, stereo, frame, cameras,
//                                model transform, window and offscreen buffers, then overlays
//   render_scene quick MODEL...  the default case, segmentation and every visual flag only
//   render_scene 2d MODEL...     also text, overlays, labels, pixels and buffers after the first
//   render_scene small MODEL...  (with either of the above) the shadow map at most 1024 wide:
//                                its size only scales the depth pass, at 4096 a quarter of a
//                                quick run's time under llvmpipe and more of a full run's
//   RENDER_PPM=DIR render_scene  also writes each frame as DIR/<model>-<case>.ppm
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <mujoco/mujoco.h>

#define W 320
#define H 240
static unsigned char buffer[4 * W * H];
static unsigned char rgb[3 * W * H];
static float depth[W * H];
static int nmodel;
static int quick, twod, small;

static unsigned long long fnv(const void* p, size_t n) {
  const unsigned char* b = (const unsigned char*)p;
  unsigned long long h = 1469598103934665603ULL;
  for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 1099511628211ULL;
  return h;
}

static void write_ppm(const char* what, mjrRect r) {
  const char* dir = getenv("RENDER_PPM");
  if (!dir) return;
  char path[1000];
  snprintf(path, sizeof path, "%s/%d-%s.ppm", dir, nmodel, what);
  FILE* f = fopen(path, "wb");
  if (!f) return;
  fprintf(f, "P6\n%d %d\n255\n", r.width, r.height);
  for (int y = r.height - 1; y >= 0; y--) fwrite(rgb + 3 * y * r.width, 3, r.width, f);
  fclose(f);
}

// reads back the viewport and prints the hashes of color and depth
static void readback(const char* what, mjrRect r, const mjrContext* con) {
  memset(rgb, 0, sizeof rgb);
  memset(depth, 0, sizeof depth);
  mjr_readPixels(rgb, depth, r, con);
  long lit = 0;
  for (int i = 0; i < 3 * r.width * r.height; i++) lit += rgb[i] != 0;
  printf(" %s lit %ld rgb %016llx depth %016llx glerror %d\n", what, lit,
         fnv(rgb, 3 * (size_t)r.width * r.height), fnv(depth, sizeof(float) * r.width * r.height),
         mjr_getError());
  write_ppm(what, r);
}

// a state with motion, contacts, controls and an applied force
static void state(const mjModel* m, mjData* d) {
  mj_resetData(m, d);
  if (m->nkey) mj_resetDataKeyframe(m, d, 0);
  for (int t = 0; t < 40; t++) {
    for (int i = 0; i < m->nu; i++) d->ctrl[i] = sin(0.1 * t + i);
    mj_step(m, d);
  }
  mj_forward(m, d);
}

// options of case k (false when k is past the last)
static int configure(const mjModel* m, const mjData* d, int k, mjvOption* opt, mjvCamera* cam,
                     mjvPerturb* pert, mjvScene* scn, char* name) {
  mjv_defaultOption(opt);
  mjv_defaultFreeCamera(m, cam);
  mjv_defaultPerturb(pert);
  for (int i = 0; i < mjNRNDFLAG; i++) scn->flags[i] = i == mjRND_SKYBOX || i == mjRND_SHADOW ||
                                                       i == mjRND_REFLECTION || i == mjRND_FOG ||
                                                       i == mjRND_HAZE || i == mjRND_CULL_FACE;
  scn->stereo = mjSTEREO_NONE;
  scn->framewidth = 0;
  scn->enabletransform = 0;
  scn->scale = 1;
  sprintf(name, "case%d", k);
  if (k == 0) return 1;
  if (k <= mjNRNDFLAG) {  // each rendering flag flipped
    scn->flags[k - 1] = !scn->flags[k - 1];
    return 1;
  }
  k -= mjNRNDFLAG + 1;
  if (k == 0) {  // segmentation by id
    scn->flags[mjRND_SEGMENT] = scn->flags[mjRND_IDCOLOR] = 1;
    return 1;
  }
  k--;
  if (k < 3) {  // every visual flag and group, labels and frames
    for (int i = 0; i < mjNVISFLAG; i++) opt->flags[i] = 1;
    for (int i = 0; i < mjNGROUP; i++) {
      opt->geomgroup[i] = opt->sitegroup[i] = opt->jointgroup[i] = 1;
      opt->tendongroup[i] = opt->actuatorgroup[i] = opt->skingroup[i] = 1;
    }
    opt->label = k == 0 ? mjLABEL_BODY : k == 1 ? mjLABEL_GEOM : mjLABEL_CONTACTFORCE;
    opt->frame = k == 0 ? mjFRAME_BODY : mjFRAME_NONE;
    if (k == 2) scn->flags[mjRND_ADDITIVE] = 1;
    return 1;
  }
  k -= 3;
  if (k == 0) {  // contacts and their forces
    opt->flags[mjVIS_CONTACTPOINT] = opt->flags[mjVIS_CONTACTFORCE] = 1;
    opt->flags[mjVIS_TRANSPARENT] = 1;
    return 1;
  }
  k--;
  if (k < 2) {  // stereo side by side, quad-buffered (falls back); a frame
    scn->stereo = k ? mjSTEREO_QUADBUFFERED : mjSTEREO_SIDEBYSIDE;
    scn->framewidth = 5 + 3 * k;
    scn->framergb[0] = 0.9f;
    scn->framergb[1] = 0.2f;
    scn->framergb[2] = 0.1f * k;
    return 1;
  }
  k -= 2;
  if (k == 0) {  // model transform
    scn->enabletransform = 1;
    scn->translate[0] = 0.1f;
    scn->translate[2] = -0.2f;
    scn->rotate[0] = 0.9f;
    scn->rotate[1] = 0.1f;
    scn->rotate[2] = 0.3f;
    scn->rotate[3] = 0.2f;
    scn->scale = 0.7f;
    return 1;
  }
  k--;
  if (k == 0) {  // tracking the last body, closer
    cam->type = mjCAMERA_TRACKING;
    cam->trackbodyid = m->nbody - 1;
    cam->distance *= 0.5;
    cam->azimuth += 70;
    cam->elevation = -10;
    return 1;
  }
  k--;
  if (k < 2 && k < m->ncam) {
    cam->type = mjCAMERA_FIXED;
    cam->fixedcamid = k;
    return 1;
  }
  k -= 2;
  if (k == 0) {  // a perturbed, selected body
    if (m->nbody < 2) return 1;
    int b = m->nbody - 1;
    pert->select = b;
    pert->active = mjPERT_TRANSLATE;
    for (int i = 0; i < 3; i++) pert->refpos[i] = d->xipos[3 * b + i] + 0.1;
    mju_copy4(pert->refquat, d->xquat + 4 * b);
    opt->label = mjLABEL_SELECTION;
    return 1;
  }
  return 0;
}

// a label of a NaN value (a diverged simulation) without its sign: the sign of a NaN that
// arithmetic produces is unspecified (C compilers and Rust may order operands either way)
static void nan_labels(mjvScene* scn) {
  for (int i = 0; i < scn->ngeom; i++) {
    char* label = scn->geoms[i].label;
    if (!strcmp(label, "-nan")) strcpy(label, "nan");
  }
}

static void overlays(const mjrContext* con, mjrRect r) {
  const char* t1 = "Time\nSize\nFPS\nNo 1\nlonger\n\n";
  const char* t2 = "0.123 s\n4 x 5\n60\n  x  \n1234567890 abcdefghijklmnopqrstuvwxyz\n";
  for (int font = 0; font < 3; font++) {
    for (int g = 0; g < 4; g++) {
      mjr_rectangle(r, 0.1f, 0.2f, 0.3f, 1);
      mjr_overlay(font, g, r, t1, g == 3 ? NULL : t2, con);
      char what[100];
      sprintf(what, "overlay-font%d-grid%d", font, g);
      readback(what, r, con);
    }
    mjr_rectangle(r, 0, 0, 0, 1);
    mjr_text(font, "Left text ~!@#$%^&*()_+{}|:\"<>?", con, 0.05f, 0.9f, 1, 0.5f, 0.2f);
    mjr_text(font, "middle", con, 0.5f, 0.5f, 0.2f, 1, 0.2f);
    mjr_text(font, "", con, 0.5f, 0.2f, 1, 1, 1);
    mjr_text(font, "edge", con, 0.99f, 0.01f, 1, 1, 1);
    char what[100];
    sprintf(what, "text-font%d", font);
    readback(what, r, con);
  }
  mjr_rectangle(r, 0, 0, 0, 1);
  for (int i = 0; i < 6; i++) {
    mjrRect v = {10 + 90 * i, 20 + 60 * i, 80 + 20 * i, 30 + 10 * i};
    mjr_rectangle(v, 0.2f * i, 1 - 0.15f * i, 0.5f, 0.3f + 0.1f * i);
    mjr_label(v, i % 3, i == 5 ? NULL : "Label text", 0.3f, 0.3f + 0.1f * i, 0.8f, 1,
              1, 1 - 0.1f * i, 0.2f, con);
  }
  readback("rectangles-labels", r, con);
}

// text at every font scale; pixels drawn and blitted; auxiliary buffers
static void buffers(mjrContext* con, mjrRect full) {
  mjr_setBuffer(mjFB_WINDOW, con);
  for (int scale = 50; scale <= 300; scale += 50) {
    mjr_changeFont(scale, con);
    mjr_rectangle(full, 0.1f, 0.1f, 0.1f, 1);
    for (int font = 0; font < 3; font++) {
      mjr_text(font, "Scale AaBbGgQq 0123 ,.;:", con, 0.02f, 0.8f - 0.25f * font, 1, 1, 0.5f);
    }
    mjr_overlay(mjFONT_NORMAL, mjGRID_BOTTOMRIGHT, full, "a\nb", "1\n2", con);
    char what[100];
    sprintf(what, "font-scale%d", scale);
    readback(what, full, con);
  }
  mjr_changeFont(mjFONTSCALE_150, con);
  // pixels drawn with and without depth, at an offset and clipped
  static unsigned char pix[3 * W * H];
  static float dep[W * H];
  for (int i = 0; i < W * H; i++) {
    pix[3 * i] = i % 251;
    pix[3 * i + 1] = (i / W) % 256;
    pix[3 * i + 2] = (i * 7) % 253;
    dep[i] = (float)(i % 1000) / 1000;
  }
  mjr_rectangle(full, 0, 0, 0, 1);
  mjrRect small = {0, 0, 100, 60};
  mjr_drawPixels(pix, NULL, small, con);
  mjrRect off = {W - 50, H - 30, 100, 60};
  mjr_drawPixels(pix, dep, off, con);
  mjrRect mid = {120, 80, 64, 48};
  mjr_drawPixels(pix, dep, mid, con);
  readback("drawpixels", full, con);
  // the offscreen buffer blitted into the window, scaled, color and depth
  mjr_setBuffer(mjFB_OFFSCREEN, con);
  mjrRect r = mjr_maxViewport(con);
  mjr_rectangle(r, 0.3f, 0.6f, 0.9f, 1);
  mjr_text(mjFONT_BIG, "blit", con, 0.3f, 0.5f, 1, 0, 0);
  for (int k = 0; k < 3; k++) {
    mjrRect dst = {10 * k, 5 * k, W / (k + 1), H / (k + 1)};
    mjr_blitBuffer(r, dst, k != 1, k != 0, con);
  }
  mjr_setBuffer(mjFB_WINDOW, con);
  readback("blitbuffer", full, con);
  // auxiliary buffers drawn into and blitted out
  for (int a = 0; a < 2; a++) {
    mjr_addAux(a, 200 + 40 * a, 120, a ? 4 : 0, con);
    mjr_setAux(a, con);
    mjrRect ar = {0, 0, 200 + 40 * a, 120};
    mjr_rectangle(ar, 0.2f * a, 0.5f, 0.3f, 1);
    mjr_text(mjFONT_SHADOW, a ? "aux one" : "aux zero", con, 0.1f, 0.5f, 1, 1, 1);
    mjr_restoreBuffer(con);
  }
  mjr_setBuffer(mjFB_WINDOW, con);
  mjr_rectangle(full, 0, 0, 0, 1);
  mjrRect a0 = {0, 0, 200, 120}, a1 = {20, 10, 200, 100};
  mjr_blitAux(0, a0, 5, 7, con);
  mjr_blitAux(1, a1, 100, 120, con);
  readback("aux", full, con);
}

static void model(const char* file) {
  char err[1000] = "";
  mjModel* m = mj_loadXML(file, NULL, err, sizeof err);
  printf("model %s\n", file);
  if (!m) {
    printf(" load error: %s\n", err);
    return;
  }
  mjData* d = mj_makeData(m);
  state(m, d);
  mjrContext con;
  mjr_defaultContext(&con);
  if (small && m->vis.quality.shadowsize > 1024) m->vis.quality.shadowsize = 1024;
  mjr_makeContext(m, &con, mjFONTSCALE_150);
  mjvScene scn;
  mjv_defaultScene(&scn);
  mjv_makeScene(m, &scn, 2000);
  mjvOption opt;
  mjvCamera cam;
  mjvPerturb pert;
  char name[100];
  mjrRect full = {0, 0, W, H};
  for (int buf = 0; buf < 2; buf++) {
    mjr_setBuffer(buf ? mjFB_OFFSCREEN : mjFB_WINDOW, &con);
    mjrRect r = buf ? mjr_maxViewport(&con) : full;
    if (r.width > W) r.width = W;
    if (r.height > H) r.height = H;
    for (int k = 0; configure(m, d, k, &opt, &cam, &pert, &scn, name); k++) {
      if (!buf && k > 0) break;  // the window buffer: the default case only
      if (quick && k != 0 && k != mjNRNDFLAG + 1 && k != mjNRNDFLAG + 2) continue;
      mjv_updateScene(m, d, &opt, &pert, &cam, mjCAT_ALL, &scn);
      nan_labels(&scn);
      mjr_render(r, &scn, &con);
      char what[120];
      sprintf(what, "%s-%s", buf ? "off" : "win", name);
      readback(what, r, &con);
    }
    if (buf) {  // a smaller viewport inside the buffer
      mjrRect v = {30, 20, r.width / 2, r.height / 2};
      configure(m, d, 0, &opt, &cam, &pert, &scn, name);
      mjv_updateScene(m, d, &opt, &pert, &cam, mjCAT_ALL, &scn);
      mjr_render(v, &scn, &con);
      readback("off-subviewport", r, &con);
    }
  }
  if (nmodel == 0 && twod) {
    overlays(&con, full);
    buffers(&con, full);
  }
  mjv_freeScene(&scn);
  mjr_freeContext(&con);
  mj_deleteData(d);
  mj_deleteModel(m);
}

int main(int argc, char** argv) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) {
    fprintf(stderr, "no OSMesa context\n");
    return 2;
  }
  int a = 1;
  for (; a < argc; a++) {
    if (!strcmp(argv[a], "quick")) {
      quick = 1;
    } else if (!strcmp(argv[a], "2d")) {
      twod = 1;
    } else if (!strcmp(argv[a], "small")) {
      small = 1;
    } else {
      break;
    }
  }
  for (; a < argc; a++, nmodel++) model(argv[a]);
  return 0;
}
