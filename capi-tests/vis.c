// Abstract visualization (mjv_) printed field by field, floats exactly (%a), for comparison
// against 2.2.2.
//   vis defaults            default structs, the free camera and scene buffers of no model
//   vis scene MODEL...      per model: the scene buffers after mjv_makeScene
#include <stdio.h>
#include <string.h>
#include <mujoco/mujoco.h>

static void pf(const char* name, const float* v, int n) {
  printf("%s", name);
  for (int i = 0; i < n; i++) printf(" %a", (double)v[i]);
  printf("\n");
}

static void pd(const char* name, const mjtNum* v, int n) {
  printf("%s", name);
  for (int i = 0; i < n; i++) printf(" %a", v[i]);
  printf("\n");
}

static void pi(const char* name, const int* v, int n) {
  printf("%s", name);
  for (int i = 0; i < n; i++) printf(" %d", v[i]);
  printf("\n");
}

static void pb(const char* name, const mjtByte* v, int n) {
  printf("%s ", name);
  for (int i = 0; i < n; i++) printf("%d", v[i]);
  printf("\n");
}

static void camera(const char* name, const mjvCamera* c) {
  printf("%s type %d fixedcamid %d trackbodyid %d\n", name, c->type, c->fixedcamid,
         c->trackbodyid);
  pd(" lookat", c->lookat, 3);
  pd(" distance azimuth elevation", &c->distance, 3);
}

static void perturb(const mjvPerturb* p) {
  printf("perturb select %d skinselect %d active %d active2 %d\n", p->select, p->skinselect,
         p->active, p->active2);
  pd(" refpos", p->refpos, 3);
  pd(" refquat", p->refquat, 4);
  pd(" localpos", p->localpos, 3);
  pd(" scale", &p->scale, 1);
}

static void option(const mjvOption* o) {
  printf("option label %d frame %d\n", o->label, o->frame);
  pb(" geomgroup", o->geomgroup, mjNGROUP);
  pb(" sitegroup", o->sitegroup, mjNGROUP);
  pb(" jointgroup", o->jointgroup, mjNGROUP);
  pb(" tendongroup", o->tendongroup, mjNGROUP);
  pb(" actuatorgroup", o->actuatorgroup, mjNGROUP);
  pb(" skingroup", o->skingroup, mjNGROUP);
  pb(" flags", o->flags, mjNVISFLAG);
}

// mjvFigure has no padding: print its bytes, 64 to a line, skipping lines of zeros
static void figure(const mjvFigure* f) {
  const unsigned char* b = (const unsigned char*)f;
  printf("figure %zu bytes\n", sizeof(mjvFigure));
  for (size_t at = 0; at < sizeof(mjvFigure); at += 64) {
    size_t n = sizeof(mjvFigure) - at < 64 ? sizeof(mjvFigure) - at : 64;
    int nonzero = 0;
    for (size_t i = 0; i < n; i++) nonzero |= b[at + i];
    if (!nonzero) continue;
    printf(" %6zu ", at);
    for (size_t i = 0; i < n; i++) printf("%02x", b[at + i]);
    printf("\n");
  }
}

static void scene_header(const mjvScene* s) {
  printf("scene maxgeom %d ngeom %d nskin %d nlight %d\n", s->maxgeom, s->ngeom, s->nskin,
         s->nlight);
  printf(" buffers geoms %d geomorder %d skin %d %d %d %d %d\n", s->geoms != NULL,
         s->geomorder != NULL, s->skinfacenum != NULL, s->skinvertadr != NULL,
         s->skinvertnum != NULL, s->skinvert != NULL, s->skinnormal != NULL);
  printf(" enabletransform %d stereo %d framewidth %d\n", s->enabletransform, s->stereo,
         s->framewidth);
  pf(" translate", s->translate, 3);
  pf(" rotate", s->rotate, 4);
  pf(" scale", &s->scale, 1);
  pb(" flags", s->flags, mjNRNDFLAG);
  pf(" framergb", s->framergb, 3);
  for (int i = 0; i < s->nskin; i++) {
    printf(" skin %d facenum %d vertadr %d vertnum %d\n", i, s->skinfacenum[i],
           s->skinvertadr[i], s->skinvertnum[i]);
  }
}

static int defaults(void) {
  mjvCamera cam;
  memset(&cam, 0x5a, sizeof cam);
  mjv_defaultCamera(&cam);
  camera("camera", &cam);
  mjvPerturb pert;
  memset(&pert, 0x5a, sizeof pert);
  mjv_defaultPerturb(&pert);
  perturb(&pert);
  mjvOption opt;
  memset(&opt, 0x5a, sizeof opt);
  mjv_defaultOption(&opt);
  option(&opt);
  static mjvFigure fig;
  memset(&fig, 0x5a, sizeof fig);
  mjv_defaultFigure(&fig);
  figure(&fig);
  mjvScene scn;
  memset(&scn, 0x5a, sizeof scn);
  mjv_defaultScene(&scn);
  scene_header(&scn);
  for (int maxgeom = -1; maxgeom <= 1000; maxgeom += 1001) {
    mjv_makeScene(NULL, &scn, maxgeom);
    scene_header(&scn);
    mjv_freeScene(&scn);
    scene_header(&scn);
  }
  return 0;
}

static int scene(int argc, char** argv) {
  for (int k = 2; k < argc; k++) {
    char err[1000] = "";
    mjModel* m = mj_loadXML(argv[k], NULL, err, sizeof err);
    printf("model %s\n", argv[k]);
    if (!m) {
      printf(" load error: %s\n", err);
      continue;
    }
    mjvCamera cam;
    mjv_defaultFreeCamera(m, &cam);
    camera("freecamera", &cam);
    mjvScene scn;
    mjv_defaultScene(&scn);
    mjv_makeScene(m, &scn, 2000);
    scene_header(&scn);
    mjv_makeScene(m, &scn, 10);
    scene_header(&scn);
    mjv_freeScene(&scn);
    mj_deleteModel(m);
  }
  return 0;
}

int main(int argc, char** argv) {
  if (argc >= 2 && !strcmp(argv[1], "defaults")) return defaults();
  if (argc >= 2 && !strcmp(argv[1], "scene")) return scene(argc, argv);
  fprintf(stderr, "usage: vis defaults | vis scene MODEL...\n");
  return 2;
}
