// Prints the memory layout of the 2.2.2 API: offset and size of every struct field, size of
// every struct, every enum value and numeric define. Compiled once against Debian's headers and
// once against ours (include/); the layout test requires identical output.

#include <stddef.h>
#include <stdio.h>

#include <mujoco/mujoco.h>
#include <mujoco/mjxmacro.h>

#define FIELD(S, f) \
  printf("%s.%s offset=%zu size=%zu\n", #S, #f, offsetof(S, f), sizeof(((S*)0)->f))

// pointer fields also report their element size
#define PFIELD(S, f) \
  printf("%s.%s offset=%zu size=%zu elem=%zu\n", #S, #f, offsetof(S, f), \
         sizeof(((S*)0)->f), sizeof(*((S*)0)->f))

#define SIZE(T) printf("sizeof(%s)=%zu\n", #T, sizeof(T))

int main(void) {
  // struct sizes
  SIZE(mjtNum);
  SIZE(mjtByte);
  SIZE(mjModel);
  SIZE(mjData);
  SIZE(mjOption);
  SIZE(mjVisual);
  SIZE(mjStatistic);
  SIZE(mjContact);
  SIZE(mjLROpt);
  SIZE(mjVFS);
  SIZE(mjSolverStat);
  SIZE(mjWarningStat);
  SIZE(mjTimerStat);

  // mjOption, from the X-macros
#define X(type, name) FIELD(mjOption, name);
  MJOPTION_FLOATS
  MJOPTION_INTS
#undef X
#define X(name, dim) FIELD(mjOption, name);
  MJOPTION_VECTORS
#undef X

  // mjModel, from the X-macros and the fields they leave out
#define X(name) FIELD(mjModel, name);
  MJMODEL_INTS
#undef X
  FIELD(mjModel, opt);
  FIELD(mjModel, vis);
  FIELD(mjModel, stat);
  FIELD(mjModel, buffer);
#define X(type, name, nr, nc) PFIELD(mjModel, name);
  MJMODEL_POINTERS
#undef X

  // mjData, from the X-macros and the fields they leave out
#define X(type, name) FIELD(mjData, name);
  MJDATA_SCALAR
#undef X
#define X(type, name, nr, nc) FIELD(mjData, name);
  MJDATA_VECTOR
#undef X
  FIELD(mjData, buffer);
  FIELD(mjData, stack);
#define X(type, name, nr, nc) PFIELD(mjData, name);
  MJDATA_POINTERS
#undef X

  // mjVisual
#define V(f) FIELD(mjVisual, f)
  V(global); V(global.fovy); V(global.ipd); V(global.azimuth); V(global.elevation);
  V(global.linewidth); V(global.glow); V(global.offwidth); V(global.offheight);
  V(quality); V(quality.shadowsize); V(quality.offsamples); V(quality.numslices);
  V(quality.numstacks); V(quality.numquads);
  V(headlight); V(headlight.ambient); V(headlight.diffuse); V(headlight.specular);
  V(headlight.active);
  V(map); V(map.stiffness); V(map.stiffnessrot); V(map.force); V(map.torque); V(map.alpha);
  V(map.fogstart); V(map.fogend); V(map.znear); V(map.zfar); V(map.haze); V(map.shadowclip);
  V(map.shadowscale); V(map.actuatortendon);
  V(scale); V(scale.forcewidth); V(scale.contactwidth); V(scale.contactheight);
  V(scale.connect); V(scale.com); V(scale.camera); V(scale.light); V(scale.selectpoint);
  V(scale.jointlength); V(scale.jointwidth); V(scale.actuatorlength); V(scale.actuatorwidth);
  V(scale.framelength); V(scale.framewidth); V(scale.constraint); V(scale.slidercrank);
  V(rgba); V(rgba.fog); V(rgba.haze); V(rgba.force); V(rgba.inertia); V(rgba.joint);
  V(rgba.actuator); V(rgba.actuatornegative); V(rgba.actuatorpositive); V(rgba.com);
  V(rgba.camera); V(rgba.light); V(rgba.selectpoint); V(rgba.connect); V(rgba.contactpoint);
  V(rgba.contactforce); V(rgba.contactfriction); V(rgba.contacttorque); V(rgba.contactgap);
  V(rgba.rangefinder); V(rgba.constraint); V(rgba.slidercrank); V(rgba.crankbroken);
#undef V

  // mjStatistic
  FIELD(mjStatistic, meaninertia);
  FIELD(mjStatistic, meanmass);
  FIELD(mjStatistic, meansize);
  FIELD(mjStatistic, extent);
  FIELD(mjStatistic, center);

  // mjContact
  FIELD(mjContact, dist);
  FIELD(mjContact, pos);
  FIELD(mjContact, frame);
  FIELD(mjContact, includemargin);
  FIELD(mjContact, friction);
  FIELD(mjContact, solref);
  FIELD(mjContact, solimp);
  FIELD(mjContact, mu);
  FIELD(mjContact, H);
  FIELD(mjContact, dim);
  FIELD(mjContact, geom1);
  FIELD(mjContact, geom2);
  FIELD(mjContact, exclude);
  FIELD(mjContact, efc_address);

  // mjLROpt
  FIELD(mjLROpt, mode);
  FIELD(mjLROpt, useexisting);
  FIELD(mjLROpt, uselimit);
  FIELD(mjLROpt, accel);
  FIELD(mjLROpt, maxforce);
  FIELD(mjLROpt, timeconst);
  FIELD(mjLROpt, timestep);
  FIELD(mjLROpt, inttotal);
  FIELD(mjLROpt, inteval);
  FIELD(mjLROpt, tolrange);

  // mjVFS
  FIELD(mjVFS, nfile);
  FIELD(mjVFS, filename);
  FIELD(mjVFS, filesize);
  FIELD(mjVFS, filedata);

  // diagnostics
  FIELD(mjSolverStat, improvement);
  FIELD(mjSolverStat, gradient);
  FIELD(mjSolverStat, lineslope);
  FIELD(mjSolverStat, nactive);
  FIELD(mjSolverStat, nchange);
  FIELD(mjSolverStat, neval);
  FIELD(mjSolverStat, nupdate);
  FIELD(mjWarningStat, lastinfo);
  FIELD(mjWarningStat, number);
  FIELD(mjTimerStat, duration);
  FIELD(mjTimerStat, number);

  // enum values and numeric defines
#define E(name) printf("enum %s=%lld\n", #name, (long long)(name));
#define D(name) printf("define %s=%.17g\n", #name, (double)(name));
#include "layout_enums.h"
#undef E
#undef D
  return 0;
}
