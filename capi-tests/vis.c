// Abstract visualization (mjv_) printed field by field, floats exactly (%a), for comparison
// against 2.2.2.
//   vis defaults            default structs, the free camera and scene buffers of no model
//   vis scene MODEL...      per model: the scene buffers after mjv_makeScene
//   vis update MODEL...     per model, at a state after 40 steps: mjv_updateScene under every
//                           option, label and frame mode, category, perturbation and camera
//                           (a hash of the whole scene; update-verbose prints it)
//   vis interact MODEL...   per model: camera queries, mouse motion of camera, model and
//                           perturbation, perturbation forces and poses, selection on a grid
#define _GNU_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
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

// ---------------------------------------------------------------- mjv_updateScene

static void fpf(FILE* f, const char* name, const float* v, int n) {
  fprintf(f, "%s", name);
  for (int i = 0; i < n; i++) fprintf(f, " %a", (double)v[i]);
  fprintf(f, "\n");
}

static void fbits(FILE* f, const char* name, const float* v, int n) {
  fprintf(f, "%s", name);
  for (int i = 0; i < n; i++) {
    unsigned u;
    memcpy(&u, v + i, 4);
    fprintf(f, "%s%08x", i % 12 ? " " : "\n ", u);
  }
  fprintf(f, "\n");
}

// the scene as text: geoms (not camdist and transparent, which the renderer sets), lights,
// GL cameras, skins
static void dump_scene(FILE* f, const mjvScene* s) {
  fprintf(f, "ngeom %d nlight %d enabletransform %d\n", s->ngeom, s->nlight,
          s->enabletransform);
  for (int i = 0; i < s->ngeom; i++) {
    const mjvGeom* g = s->geoms + i;
    fprintf(f, "geom %d type %d dataid %d obj %d %d category %d tex %d %d %d segid %d\n", i,
            g->type, g->dataid, g->objtype, g->objid, g->category, g->texid, g->texuniform,
            g->texcoord, g->segid);
    fpf(f, " texrepeat", g->texrepeat, 2);
    fpf(f, " size", g->size, 3);
    fpf(f, " pos", g->pos, 3);
    fpf(f, " mat", g->mat, 9);
    fpf(f, " rgba", g->rgba, 4);
    fpf(f, " material", &g->emission, 4);
    fpf(f, " modelrbound", &g->modelrbound, 1);
    fprintf(f, " label '%.99s'\n", g->label);
  }
  for (int i = 0; i < s->nlight; i++) {
    const mjvLight* l = s->lights + i;
    fprintf(f, "light %d headlight %d directional %d castshadow %d\n", i, l->headlight,
            l->directional, l->castshadow);
    fpf(f, " pos dir attenuation cutoff exponent", l->pos, 11);
    fpf(f, " ambient diffuse specular", l->ambient, 9);
  }
  for (int i = 0; i < 2; i++) {
    fprintf(f, "glcamera %d\n", i);
    fpf(f, " pos forward up", s->camera[i].pos, 9);
    fpf(f, " frustum", &s->camera[i].frustum_center, 5);
  }
  int totvert = 0;
  for (int i = 0; i < s->nskin; i++) totvert += s->skinvertnum[i];
  if (totvert) {
    fbits(f, "skinvert", s->skinvert, 3 * totvert);
    fbits(f, "skinnormal", s->skinnormal, 3 * totvert);
  }
}

static unsigned long long fnv(const char* p, size_t n) {
  unsigned long long h = 1469598103934665603ULL;
  for (size_t i = 0; i < n; i++) h = (h ^ (unsigned char)p[i]) * 1099511628211ULL;
  return h;
}

// options of configuration k (false when k is past the last)
static int configure(const mjModel* m, const mjData* d, int k, mjvOption* opt,
                     mjvPerturb* pert, mjvCamera* cam, int* catmask, int* maxgeom) {
  mjv_defaultOption(opt);
  mjv_defaultPerturb(pert);
  mjv_defaultFreeCamera(m, cam);
  *catmask = mjCAT_ALL;
  *maxgeom = 5000;
  if (k == 0) return 1;
  if (k <= mjNVISFLAG) {  // each flag flipped
    opt->flags[k - 1] = !opt->flags[k - 1];
    return 1;
  }
  k -= mjNVISFLAG + 1;
  // the rest: every flag and group on
  for (int i = 0; i < mjNVISFLAG; i++) opt->flags[i] = 1;
  for (int i = 0; i < mjNGROUP; i++) {
    opt->geomgroup[i] = opt->sitegroup[i] = opt->jointgroup[i] = 1;
    opt->tendongroup[i] = opt->actuatorgroup[i] = opt->skingroup[i] = 1;
  }
  if (k == 0) return 1;
  if (k <= 13) {
    opt->label = k;
    return 1;
  }
  k -= 14;
  if (k < 7) {
    opt->frame = k + 1;
    opt->label = mjLABEL_CONTACTFORCE;
    return 1;
  }
  k -= 7;
  if (k < 3) {
    *catmask = 1 << k;
    return 1;
  }
  k -= 3;
  if (k < 4) {  // perturbations of the last body
    int b = m->nbody - 1;
    pert->select = b;
    pert->skinselect = m->nskin ? 0 : -1;
    pert->active = k & 1 ? mjPERT_TRANSLATE : mjPERT_ROTATE;
    pert->active2 = k & 2 ? mjPERT_ROTATE : mjPERT_TRANSLATE;
    for (int i = 0; i < 3; i++) {
      pert->refpos[i] = d->xipos[3 * b + i] + 0.1 * (i + 1);
      pert->localpos[i] = 0.01 * (i + 1);
    }
    double q[4] = {0.9, 0.1, 0.2, 0.3};
    mju_normalize4(q);
    mju_copy4(pert->refquat, q);
    opt->label = k < 2 ? mjLABEL_SELECTION : mjLABEL_SELPNT;
    return 1;
  }
  k -= 4;
  if (k == 0) {  // tracking the last body
    cam->type = mjCAMERA_TRACKING;
    cam->trackbodyid = m->nbody - 1;
    return 1;
  }
  k -= 1;
  if (k < 3 && k < m->ncam) {
    cam->type = mjCAMERA_FIXED;
    cam->fixedcamid = k;
    return 1;
  }
  k -= 3;
  if (k < 2) {  // full geom buffers
    *maxgeom = k ? 1 : 10;
    return 1;
  }
  return 0;
}

// a state with motion, contacts, controls and an applied force
static void state(const mjModel* m, mjData* d) {
  mj_resetData(m, d);
  if (m->nkey) mj_resetDataKeyframe(m, d, 0);
  for (int t = 0; t < 40; t++) {
    for (int i = 0; i < m->nu; i++) d->ctrl[i] = sin(0.1 * t + i);
    mj_step(m, d);
  }
  if (m->nbody > 1) {
    double frc[6] = {1, 2, 3, 0.1, 0, 0};
    mju_copy(d->xfrc_applied + 6 * (m->nbody - 1), frc, 6);
  }
  mj_forward(m, d);
}

static int update(int argc, char** argv) {
  int verbose = !strcmp(argv[1], "update-verbose");
  for (int a = 2; a < argc; a++) {
    char err[1000] = "";
    mjModel* m = mj_loadXML(argv[a], NULL, err, sizeof err);
    printf("model %s\n", argv[a]);
    if (!m) {
      printf(" load error: %s\n", err);
      continue;
    }
    mjData* d = mj_makeData(m);
    state(m, d);
    mjvScene scn;
    mjv_defaultScene(&scn);
    int made = -1;
    mjvOption opt;
    mjvPerturb pert;
    mjvCamera cam;
    int catmask, maxgeom;
    for (int k = 0; configure(m, d, k, &opt, &pert, &cam, &catmask, &maxgeom); k++) {
      if (maxgeom != made) {
        mjv_makeScene(m, &scn, maxgeom);
        made = maxgeom;
      }
      char* buf = NULL;
      size_t len = 0;
      FILE* f = open_memstream(&buf, &len);
      mjv_updateScene(m, d, &opt, &pert, &cam, catmask, &scn);
      dump_scene(f, &scn);
      fprintf(f, "camera %d lookat %a %a %a\n", cam.type, cam.lookat[0], cam.lookat[1],
              cam.lookat[2]);
      fprintf(f, "warning vgeomfull %d %d\n", d->warning[mjWARN_VGEOMFULL].number,
              d->warning[mjWARN_VGEOMFULL].lastinfo);
      fclose(f);
      printf(" config %d ngeom %d hash %016llx\n", k, scn.ngeom, fnv(buf, len));
      if (verbose) fputs(buf, stdout);
      free(buf);
    }
    mjv_freeScene(&scn);
    mj_deleteData(d);
    mj_deleteModel(m);
  }
  return 0;
}

// ---------------------------------------------------------------- interaction

static void pglcam(const char* name, const mjvGLCamera* c) {
  printf("%s", name);
  fpf(stdout, " pos forward up", c->pos, 9);
  fpf(stdout, " frustum", &c->frustum_center, 5);
}

static void pscn_transform(const mjvScene* s) {
  pf(" translate", s->translate, 3);
  pf(" rotate", s->rotate, 4);
  pf(" scale", &s->scale, 1);
}

static void camera_info(const mjvScene* scn) {
  mjtNum head[3], fwd[3], up[3];
  mjv_cameraInModel(head, fwd, up, scn);
  pd(" inmodel head", head, 3);
  pd(" inmodel forward", fwd, 3);
  pd(" inmodel up", up, 3);
  mjv_cameraInRoom(head, fwd, up, scn);
  pd(" inroom head", head, 3);
  pd(" inroom forward", fwd, 3);
  pd(" inroom up", up, 3);
  mjtNum h = mjv_frustumHeight(scn);
  pd(" frustumheight", &h, 1);
  mjtNum v[3] = {1, 2, 3}, res[3];
  mjv_alignToCamera(res, v, fwd);
  pd(" aligned", res, 3);
}

static int interact(int argc, char** argv) {
  for (int a = 2; a < argc; a++) {
    char err[1000] = "";
    mjModel* m = mj_loadXML(argv[a], NULL, err, sizeof err);
    printf("model %s\n", argv[a]);
    if (!m) {
      printf(" load error: %s\n", err);
      continue;
    }
    mjData* d = mj_makeData(m);
    state(m, d);
    mjvScene scn;
    mjv_defaultScene(&scn);
    mjv_makeScene(m, &scn, 5000);
    mjvOption opt;
    mjv_defaultOption(&opt);
    opt.flags[mjVIS_SKIN] = 1;
    mjvPerturb pert;
    mjv_defaultPerturb(&pert);
    mjvCamera cam;
    mjv_defaultFreeCamera(m, &cam);
    mjv_updateScene(m, d, &opt, &pert, &cam, mjCAT_ALL, &scn);
    camera_info(&scn);
    mjvGLCamera avg = mjv_averageCamera(scn.camera, scn.camera + 1);
    pglcam("average", &avg);

    // the camera moved by the mouse: free, then tracking
    for (int type = 0; type < 2; type++) {
      mjv_defaultFreeCamera(m, &cam);
      if (type) {
        cam.type = mjCAMERA_TRACKING;
        cam.trackbodyid = m->nbody - 1;
      }
      for (int action = mjMOUSE_ROTATE_V; action <= mjMOUSE_ZOOM; action++) {
        for (int rep = 0; rep < 3; rep++) {
          mjv_moveCamera(m, action, 0.1 * (rep + 1), -0.05 * (rep + 2), &scn, &cam);
          mjv_updateCamera(m, d, &cam, &scn);
        }
        printf(" movecamera type %d action %d\n", type, action);
        camera(" camera", &cam);
      }
    }

    // the model moved in the room
    scn.enabletransform = 1;
    float tr[3] = {0.1f, 0.2f, 0.3f}, rot[4] = {0.9f, 0.1f, -0.2f, 0.3f};
    memcpy(scn.translate, tr, sizeof tr);
    mjtNum q[4];
    for (int i = 0; i < 4; i++) q[i] = rot[i];
    mju_normalize4(q);
    for (int i = 0; i < 4; i++) scn.rotate[i] = (float)q[i];
    scn.scale = 1.5f;
    mjtNum pos[3] = {0.3, -0.2, 0.5}, quat[4] = {0.5, 0.5, -0.5, 0.5}, p2[3], q2[4];
    mjv_room2model(p2, q2, pos, quat, &scn);
    pd(" room2model pos", p2, 3);
    pd(" room2model quat", q2, 4);
    mjv_model2room(p2, q2, pos, quat, &scn);
    pd(" model2room pos", p2, 3);
    pd(" model2room quat", q2, 4);
    camera_info(&scn);
    mjtNum roomup[3] = {0, 0, 1};
    for (int action = mjMOUSE_ROTATE_V; action <= mjMOUSE_ZOOM; action++) {
      mjv_moveModel(m, action, 0.05, -0.03, roomup, &scn);
      printf(" movemodel action %d\n", action);
      pscn_transform(&scn);
    }
    scn.enabletransform = 0;

    // perturbations of the last body and of the first child of a root
    for (int which = 0; which < 2 && m->nbody > 1; which++) {
      int sel = m->nbody - 1;
      if (which) {
        sel = -1;
        for (int b = 1; b < m->nbody && sel < 0; b++) {
          if (m->body_rootid[b] != b) sel = b;
        }
        if (sel < 0) break;
      }
      mjv_defaultPerturb(&pert);
      pert.select = sel;
      mjv_initPerturb(m, d, &scn, &pert);
      printf(" initperturb body %d\n", sel);
      perturb(&pert);
      for (int action = mjMOUSE_ROTATE_V; action <= mjMOUSE_ZOOM; action++) {
        for (int rep = 0; rep < 12; rep++) {
          mjv_movePerturb(m, d, action, 0.02 * (rep + 1), 0.03, &scn, &pert);
        }
        printf(" moveperturb action %d\n", action);
        perturb(&pert);
      }
      for (int active = 1; active <= 3; active++) {
        pert.active = active & 1;
        pert.active2 = active & 2;
        mjv_applyPerturbForce(m, d, &pert);
        pd(" xfrc_applied", d->xfrc_applied + 6 * sel, 6);
        for (int paused = 0; paused < 2; paused++) {
          mjv_applyPerturbPose(m, d, &pert, paused);
          pd(" qpos", d->qpos, m->nq < 14 ? m->nq : 14);
          if (m->nmocap) pd(" mocap", d->mocap_pos, 3);
        }
      }
      mj_forward(m, d);
    }

    // selection over the image
    mjv_updateScene(m, d, &opt, NULL, &cam, mjCAT_ALL, &scn);
    for (int iy = 0; iy <= 8; iy++) {
      for (int ix = 0; ix <= 8; ix++) {
        mjtNum selpnt[3] = {0, 0, 0};
        int geom = -7, skin = -7;
        int body = mjv_select(m, d, &opt, 1.5, ix / 8.0, iy / 8.0, &scn, selpnt, &geom, &skin);
        printf(" select %d %d body %d geom %d skin %d", ix, iy, body, geom, skin);
        pd("", selpnt, 3);
      }
    }
    mjv_freeScene(&scn);
    mj_deleteData(d);
    mj_deleteModel(m);
  }
  return 0;
}

int main(int argc, char** argv) {
  if (argc >= 2 && !strcmp(argv[1], "defaults")) return defaults();
  if (argc >= 2 && !strcmp(argv[1], "scene")) return scene(argc, argv);
  if (argc >= 2 && !strncmp(argv[1], "update", 6)) return update(argc, argv);
  if (argc >= 2 && !strcmp(argv[1], "interact")) return interact(argc, argv);
  fprintf(stderr, "usage: vis defaults | vis scene|update|update-verbose MODEL...\n");
  return 2;
}
