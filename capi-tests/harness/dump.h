// Model and data contents as records (binfile.h), driven by the X-macro field lists, and the
// reverse: a model rebuilt from the reference's records ("transplant"), data arrays restored.

#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#include <mujoco/mujoco.h>
#include <mujoco/mjxmacro.h>

#include "binfile.h"

template <class T> inline char type_code(const char*) { return 'r'; }
template <> inline char type_code<mjtNum>(const char* name) {
  size_t n = std::strlen(name);
  return (n >= 4 && !std::strcmp(name + n - 4, "quat")) ? 'q' : 'd';
}
template <> inline char type_code<float>(const char*) { return 'f'; }
template <> inline char type_code<int>(const char*) { return 'i'; }
template <> inline char type_code<mjtByte>(const char*) { return 'b'; }
template <> inline char type_code<char>(const char*) { return 'c'; }

// mjVisual fields: (member, element type)
#define RJ_VISUAL_FIELDS                                                                       \
  V(global.fovy, float) V(global.ipd, float) V(global.azimuth, float)                          \
  V(global.elevation, float) V(global.linewidth, float) V(global.glow, float)                  \
  V(global.offwidth, int) V(global.offheight, int) V(quality.shadowsize, int)                  \
  V(quality.offsamples, int) V(quality.numslices, int) V(quality.numstacks, int)               \
  V(quality.numquads, int) V(headlight.ambient, float) V(headlight.diffuse, float)             \
  V(headlight.specular, float) V(headlight.active, int) V(map.stiffness, float)                \
  V(map.stiffnessrot, float) V(map.force, float) V(map.torque, float) V(map.alpha, float)      \
  V(map.fogstart, float) V(map.fogend, float) V(map.znear, float) V(map.zfar, float)           \
  V(map.haze, float) V(map.shadowclip, float) V(map.shadowscale, float)                        \
  V(map.actuatortendon, float) V(scale.forcewidth, float) V(scale.contactwidth, float)         \
  V(scale.contactheight, float) V(scale.connect, float) V(scale.com, float)                    \
  V(scale.camera, float) V(scale.light, float) V(scale.selectpoint, float)                     \
  V(scale.jointlength, float) V(scale.jointwidth, float) V(scale.actuatorlength, float)        \
  V(scale.actuatorwidth, float) V(scale.framelength, float) V(scale.framewidth, float)         \
  V(scale.constraint, float) V(scale.slidercrank, float) V(rgba.fog, float)                    \
  V(rgba.haze, float) V(rgba.force, float) V(rgba.inertia, float) V(rgba.joint, float)         \
  V(rgba.actuator, float) V(rgba.actuatornegative, float) V(rgba.actuatorpositive, float)      \
  V(rgba.com, float) V(rgba.camera, float) V(rgba.light, float) V(rgba.selectpoint, float)     \
  V(rgba.connect, float) V(rgba.contactpoint, float) V(rgba.contactforce, float)               \
  V(rgba.contactfriction, float) V(rgba.contacttorque, float) V(rgba.contactgap, float)        \
  V(rgba.rangefinder, float) V(rgba.constraint, float) V(rgba.slidercrank, float)              \
  V(rgba.crankbroken, float)

// Every compiled-model field: sizes, opt, vis, stat, every array (and its buffer offset).
inline void dump_model(const mjModel* m, Writer& w) {
#define X(name) w.i1("size." #name, m->name);
  MJMODEL_INTS
#undef X
#define X(type, name) w.raw("opt." #name, type_code<type>(#name), &m->opt.name, sizeof(type));
  MJOPTION_SCALARS
#undef X
#define X(name, dim) w.d("opt." #name, m->opt.name, dim);
  MJOPTION_VECTORS
#undef X
#define V(f, type) \
  w.raw("vis." #f, type_code<type>(#f), &m->vis.f, sizeof(m->vis.f));
  RJ_VISUAL_FIELDS
#undef V
  w.d("stat.meaninertia", &m->stat.meaninertia, 1);
  w.d("stat.meanmass", &m->stat.meanmass, 1);
  w.d("stat.meansize", &m->stat.meansize, 1);
  w.d("stat.extent", &m->stat.extent, 1);
  w.d("stat.center", m->stat.center, 3);
  w.raw("raw.opt", 'r', &m->opt, sizeof(mjOption));
  w.raw("raw.vis", 'r', &m->vis, sizeof(mjVisual));
  w.raw("raw.stat", 'r', &m->stat, sizeof(mjStatistic));

  MJMODEL_POINTERS_PREAMBLE(m)
#define X(type, name, nr, nc)                                                         \
  {                                                                                   \
    int64_t off = (const char*)m->name - (const char*)m->buffer;                      \
    w.raw("offset." #name, 'o', &off, 8);                                             \
    w.raw(#name, type_code<type>(#name), m->name, sizeof(type) * (size_t)(m->nr) * (nc)); \
  }
  MJMODEL_POINTERS
#undef X
}

// A model rebuilt in plain memory from the records of dump_model; free with free_transplant.
inline mjModel* transplant_model(const Reader& r) {
  mjModel* m = (mjModel*)std::calloc(1, sizeof(mjModel));
#define X(name) r.copy("size." #name, &m->name, sizeof(int));
  MJMODEL_INTS
#undef X
  r.copy("raw.opt", &m->opt, sizeof(mjOption));
  r.copy("raw.vis", &m->vis, sizeof(mjVisual));
  r.copy("raw.stat", &m->stat, sizeof(mjStatistic));
  size_t nbuf = ((size_t)m->nbuffer + 63) / 64 * 64 + 64;
  m->buffer = std::aligned_alloc(64, nbuf);
  std::memset(m->buffer, 0, nbuf);
  MJMODEL_POINTERS_PREAMBLE(m)
#define X(type, name, nr, nc)                                                      \
  {                                                                                \
    const Rec* o = r.get("offset." #name);                                         \
    m->name = (type*)((char*)m->buffer + (o ? o->o()[0] : 0));                     \
    r.copy(#name, m->name, sizeof(type) * (size_t)(m->nr) * (nc));                 \
  }
  MJMODEL_POINTERS
#undef X
  return m;
}

inline void free_transplant(mjModel* m) {
  std::free(m->buffer);
  std::free(m);
}

// Rows and columns of an mjData array that hold results: efc arrays by nefc, contacts by ncon.
inline size_t data_count(const mjModel* m, const mjData* d, const char* name, int nr, int nc) {
  size_t rows = nr, cols = nc;
  if (nr == m->njmax) rows = d->nefc;
  if (nc == m->njmax) cols = d->nefc;
  if (nr == m->nconmax && !std::strcmp(name, "contact")) rows = d->ncon;
  return rows * cols;
}

// The detected contacts: real and integer members of each.
inline void dump_contacts(const mjData* d, Writer& w, const std::string& inst) {
  const size_t nreal = offsetof(mjContact, dim) / sizeof(mjtNum);
  for (int k = 0; k < d->ncon; k++) {
    const mjContact* con = d->contact + k;
    std::string ci = inst + "." + std::to_string(k);
    w.d("contact.real#" + ci, &con->dist, nreal);
    w.i("contact.int#" + ci, &con->dim, 5);
  }
}

// Every mjData array with results (MJDATA_POINTERS) and the deterministic scalars; arrays of
// more than max_count elements are left out (max_count 0: none).
inline void dump_data(const mjModel* m, const mjData* d, Writer& w, const std::string& inst,
                      size_t max_count = 0) {
  MJDATA_POINTERS_PREAMBLE(m)
#define X(type, name, nr, nc)                                                                \
  if (std::strcmp(#name, "contact")) {                                                       \
    size_t c = data_count(m, d, #name, m->nr, nc);                                          \
    if (!max_count || c <= max_count)                                                        \
      w.raw(std::string(#name) + "#" + inst, type_code<type>(""), d->name, sizeof(type) * c); \
  }
  MJDATA_POINTERS
#undef X
  dump_contacts(d, w, inst);
  // maxuse_stack included: the stack is taken in 2.2.2's sizes and nesting
#define X(type, name) w.raw(#name "#" + inst, type_code<type>(""), &d->name, sizeof(type));
  MJDATA_SCALAR
#undef X
  w.d("energy#" + inst, d->energy, 2);
  w.d("solver_fwdinv#" + inst, d->solver_fwdinv, 2);
  for (int k = 0; k < mjNWARNING; k++) {
    w.i("warning#" + inst + "." + std::to_string(k), &d->warning[k].lastinfo, 2);
  }
  for (int k = 0; k < d->solver_iter && k < mjNSOLVER; k++) {
    w.d("solver.real#" + inst + "." + std::to_string(k), &d->solver[k].improvement, 3);
    w.i("solver.int#" + inst + "." + std::to_string(k), &d->solver[k].nactive, 4);
  }
}

// Restores the arrays and sizes dump_data wrote for one instance (results of mj_forward).
inline bool load_data(const mjModel* m, mjData* d, const Reader& r, const std::string& inst) {
  bool ok = true;
  r.copy("ne#" + inst, &d->ne, sizeof(int));
  r.copy("nf#" + inst, &d->nf, sizeof(int));
  r.copy("nefc#" + inst, &d->nefc, sizeof(int));
  r.copy("ncon#" + inst, &d->ncon, sizeof(int));
  r.copy("time#" + inst, &d->time, sizeof(mjtNum));
  MJDATA_POINTERS_PREAMBLE(m)
#define X(type, name, nr, nc)                                                          \
  if (std::strcmp(#name, "contact")) {                                                 \
    size_t c = data_count(m, d, #name, m->nr, nc);                                    \
    ok = r.copy(std::string(#name) + "#" + inst, d->name, sizeof(type) * c) && ok;    \
  }
  MJDATA_POINTERS
#undef X
  return ok;
}

// The simulation state: what a replay copies into the other library's mjData.
#define RJ_STATE_FIELDS                                                                 \
  S(qpos, nq, 1) S(qvel, nv, 1) S(act, na, 1) S(ctrl, nu, 1) S(qacc_warmstart, nv, 1)   \
  S(mocap_pos, nmocap, 3) S(mocap_quat, nmocap, 4) S(qfrc_applied, nv, 1)              \
  S(xfrc_applied, nbody, 6) S(userdata, nuserdata, 1)

inline void dump_state(const mjModel* m, const mjData* d, Writer& w, const std::string& inst) {
  w.d("time#" + inst, &d->time, 1);
#define S(name, nr, nc) w.d(#name "#" + inst, d->name, (size_t)m->nr * nc);
  RJ_STATE_FIELDS
#undef S
}

inline bool load_state(const mjModel* m, mjData* d, const Reader& r, const std::string& inst) {
  bool ok = r.copy("time#" + inst, &d->time, sizeof(mjtNum));
#define S(name, nr, nc) ok = r.copy(#name "#" + inst, d->name, sizeof(mjtNum) * m->nr * nc) && ok;
  RJ_STATE_FIELDS
#undef S
  return ok;
}
