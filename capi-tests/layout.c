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

  // mjvisualize.h, mjrender.h, mjui.h: every struct, every field
  SIZE(mjvPerturb);
  FIELD(mjvPerturb, select);
  FIELD(mjvPerturb, skinselect);
  FIELD(mjvPerturb, active);
  FIELD(mjvPerturb, active2);
  FIELD(mjvPerturb, refpos);
  FIELD(mjvPerturb, refquat);
  FIELD(mjvPerturb, localpos);
  FIELD(mjvPerturb, scale);
  SIZE(mjvCamera);
  FIELD(mjvCamera, type);
  FIELD(mjvCamera, fixedcamid);
  FIELD(mjvCamera, trackbodyid);
  FIELD(mjvCamera, lookat);
  FIELD(mjvCamera, distance);
  FIELD(mjvCamera, azimuth);
  FIELD(mjvCamera, elevation);
  SIZE(mjvGLCamera);
  FIELD(mjvGLCamera, pos);
  FIELD(mjvGLCamera, forward);
  FIELD(mjvGLCamera, up);
  FIELD(mjvGLCamera, frustum_center);
  FIELD(mjvGLCamera, frustum_bottom);
  FIELD(mjvGLCamera, frustum_top);
  FIELD(mjvGLCamera, frustum_near);
  FIELD(mjvGLCamera, frustum_far);
  SIZE(mjvGeom);
  FIELD(mjvGeom, type);
  FIELD(mjvGeom, dataid);
  FIELD(mjvGeom, objtype);
  FIELD(mjvGeom, objid);
  FIELD(mjvGeom, category);
  FIELD(mjvGeom, texid);
  FIELD(mjvGeom, texuniform);
  FIELD(mjvGeom, texcoord);
  FIELD(mjvGeom, segid);
  FIELD(mjvGeom, texrepeat);
  FIELD(mjvGeom, size);
  FIELD(mjvGeom, pos);
  FIELD(mjvGeom, mat);
  FIELD(mjvGeom, rgba);
  FIELD(mjvGeom, emission);
  FIELD(mjvGeom, specular);
  FIELD(mjvGeom, shininess);
  FIELD(mjvGeom, reflectance);
  FIELD(mjvGeom, label);
  FIELD(mjvGeom, camdist);
  FIELD(mjvGeom, modelrbound);
  FIELD(mjvGeom, transparent);
  SIZE(mjvLight);
  FIELD(mjvLight, pos);
  FIELD(mjvLight, dir);
  FIELD(mjvLight, attenuation);
  FIELD(mjvLight, cutoff);
  FIELD(mjvLight, exponent);
  FIELD(mjvLight, ambient);
  FIELD(mjvLight, diffuse);
  FIELD(mjvLight, specular);
  FIELD(mjvLight, headlight);
  FIELD(mjvLight, directional);
  FIELD(mjvLight, castshadow);
  SIZE(mjvOption);
  FIELD(mjvOption, label);
  FIELD(mjvOption, frame);
  FIELD(mjvOption, geomgroup);
  FIELD(mjvOption, sitegroup);
  FIELD(mjvOption, jointgroup);
  FIELD(mjvOption, tendongroup);
  FIELD(mjvOption, actuatorgroup);
  FIELD(mjvOption, skingroup);
  FIELD(mjvOption, flags);
  SIZE(mjvScene);
  FIELD(mjvScene, maxgeom);
  FIELD(mjvScene, ngeom);
  FIELD(mjvScene, geoms);
  FIELD(mjvScene, geomorder);
  FIELD(mjvScene, nskin);
  FIELD(mjvScene, skinfacenum);
  FIELD(mjvScene, skinvertadr);
  FIELD(mjvScene, skinvertnum);
  FIELD(mjvScene, skinvert);
  FIELD(mjvScene, skinnormal);
  FIELD(mjvScene, nlight);
  FIELD(mjvScene, lights);
  FIELD(mjvScene, camera);
  FIELD(mjvScene, enabletransform);
  FIELD(mjvScene, translate);
  FIELD(mjvScene, rotate);
  FIELD(mjvScene, scale);
  FIELD(mjvScene, stereo);
  FIELD(mjvScene, flags);
  FIELD(mjvScene, framewidth);
  FIELD(mjvScene, framergb);
  SIZE(mjvFigure);
  FIELD(mjvFigure, flg_legend);
  FIELD(mjvFigure, flg_ticklabel);
  FIELD(mjvFigure, flg_extend);
  FIELD(mjvFigure, flg_barplot);
  FIELD(mjvFigure, flg_selection);
  FIELD(mjvFigure, flg_symmetric);
  FIELD(mjvFigure, linewidth);
  FIELD(mjvFigure, gridwidth);
  FIELD(mjvFigure, gridsize);
  FIELD(mjvFigure, gridrgb);
  FIELD(mjvFigure, figurergba);
  FIELD(mjvFigure, panergba);
  FIELD(mjvFigure, legendrgba);
  FIELD(mjvFigure, textrgb);
  FIELD(mjvFigure, linergb);
  FIELD(mjvFigure, range);
  FIELD(mjvFigure, xformat);
  FIELD(mjvFigure, yformat);
  FIELD(mjvFigure, minwidth);
  FIELD(mjvFigure, title);
  FIELD(mjvFigure, xlabel);
  FIELD(mjvFigure, linename);
  FIELD(mjvFigure, legendoffset);
  FIELD(mjvFigure, subplot);
  FIELD(mjvFigure, highlight);
  FIELD(mjvFigure, highlightid);
  FIELD(mjvFigure, selection);
  FIELD(mjvFigure, linepnt);
  FIELD(mjvFigure, linedata);
  FIELD(mjvFigure, xaxispixel);
  FIELD(mjvFigure, yaxispixel);
  FIELD(mjvFigure, xaxisdata);
  FIELD(mjvFigure, yaxisdata);
  SIZE(mjrRect);
  FIELD(mjrRect, left);
  FIELD(mjrRect, bottom);
  FIELD(mjrRect, width);
  FIELD(mjrRect, height);
  SIZE(mjrContext);
  FIELD(mjrContext, lineWidth);
  FIELD(mjrContext, shadowClip);
  FIELD(mjrContext, shadowScale);
  FIELD(mjrContext, fogStart);
  FIELD(mjrContext, fogEnd);
  FIELD(mjrContext, fogRGBA);
  FIELD(mjrContext, shadowSize);
  FIELD(mjrContext, offWidth);
  FIELD(mjrContext, offHeight);
  FIELD(mjrContext, offSamples);
  FIELD(mjrContext, fontScale);
  FIELD(mjrContext, auxWidth);
  FIELD(mjrContext, auxHeight);
  FIELD(mjrContext, auxSamples);
  FIELD(mjrContext, offFBO);
  FIELD(mjrContext, offFBO_r);
  FIELD(mjrContext, offColor);
  FIELD(mjrContext, offColor_r);
  FIELD(mjrContext, offDepthStencil);
  FIELD(mjrContext, offDepthStencil_r);
  FIELD(mjrContext, shadowFBO);
  FIELD(mjrContext, shadowTex);
  FIELD(mjrContext, auxFBO);
  FIELD(mjrContext, auxFBO_r);
  FIELD(mjrContext, auxColor);
  FIELD(mjrContext, auxColor_r);
  FIELD(mjrContext, ntexture);
  FIELD(mjrContext, textureType);
  FIELD(mjrContext, texture);
  FIELD(mjrContext, basePlane);
  FIELD(mjrContext, baseMesh);
  FIELD(mjrContext, baseHField);
  FIELD(mjrContext, baseBuiltin);
  FIELD(mjrContext, baseFontNormal);
  FIELD(mjrContext, baseFontShadow);
  FIELD(mjrContext, baseFontBig);
  FIELD(mjrContext, rangePlane);
  FIELD(mjrContext, rangeMesh);
  FIELD(mjrContext, rangeHField);
  FIELD(mjrContext, rangeBuiltin);
  FIELD(mjrContext, rangeFont);
  FIELD(mjrContext, nskin);
  FIELD(mjrContext, skinvertVBO);
  FIELD(mjrContext, skinnormalVBO);
  FIELD(mjrContext, skintexcoordVBO);
  FIELD(mjrContext, skinfaceVBO);
  FIELD(mjrContext, charWidth);
  FIELD(mjrContext, charWidthBig);
  FIELD(mjrContext, charHeight);
  FIELD(mjrContext, charHeightBig);
  FIELD(mjrContext, glInitialized);
  FIELD(mjrContext, windowAvailable);
  FIELD(mjrContext, windowSamples);
  FIELD(mjrContext, windowStereo);
  FIELD(mjrContext, windowDoublebuffer);
  FIELD(mjrContext, currentBuffer);
  SIZE(mjuiState);
  FIELD(mjuiState, nrect);
  FIELD(mjuiState, rect);
  FIELD(mjuiState, userdata);
  FIELD(mjuiState, type);
  FIELD(mjuiState, left);
  FIELD(mjuiState, right);
  FIELD(mjuiState, middle);
  FIELD(mjuiState, doubleclick);
  FIELD(mjuiState, button);
  FIELD(mjuiState, buttontime);
  FIELD(mjuiState, x);
  FIELD(mjuiState, y);
  FIELD(mjuiState, dx);
  FIELD(mjuiState, dy);
  FIELD(mjuiState, sx);
  FIELD(mjuiState, sy);
  FIELD(mjuiState, control);
  FIELD(mjuiState, shift);
  FIELD(mjuiState, alt);
  FIELD(mjuiState, key);
  FIELD(mjuiState, keytime);
  FIELD(mjuiState, mouserect);
  FIELD(mjuiState, dragrect);
  FIELD(mjuiState, dragbutton);
  SIZE(mjuiThemeSpacing);
  FIELD(mjuiThemeSpacing, total);
  FIELD(mjuiThemeSpacing, scroll);
  FIELD(mjuiThemeSpacing, label);
  FIELD(mjuiThemeSpacing, section);
  FIELD(mjuiThemeSpacing, itemside);
  FIELD(mjuiThemeSpacing, itemmid);
  FIELD(mjuiThemeSpacing, itemver);
  FIELD(mjuiThemeSpacing, texthor);
  FIELD(mjuiThemeSpacing, textver);
  FIELD(mjuiThemeSpacing, linescroll);
  FIELD(mjuiThemeSpacing, samples);
  SIZE(mjuiThemeColor);
  FIELD(mjuiThemeColor, master);
  FIELD(mjuiThemeColor, thumb);
  FIELD(mjuiThemeColor, secttitle);
  FIELD(mjuiThemeColor, sectfont);
  FIELD(mjuiThemeColor, sectsymbol);
  FIELD(mjuiThemeColor, sectpane);
  FIELD(mjuiThemeColor, shortcut);
  FIELD(mjuiThemeColor, fontactive);
  FIELD(mjuiThemeColor, fontinactive);
  FIELD(mjuiThemeColor, decorinactive);
  FIELD(mjuiThemeColor, decorinactive2);
  FIELD(mjuiThemeColor, button);
  FIELD(mjuiThemeColor, check);
  FIELD(mjuiThemeColor, radio);
  FIELD(mjuiThemeColor, select);
  FIELD(mjuiThemeColor, select2);
  FIELD(mjuiThemeColor, slider);
  FIELD(mjuiThemeColor, slider2);
  FIELD(mjuiThemeColor, edit);
  FIELD(mjuiThemeColor, edit2);
  FIELD(mjuiThemeColor, cursor);
  SIZE(struct mjuiItemSingle_);
  FIELD(struct mjuiItemSingle_, modifier);
  FIELD(struct mjuiItemSingle_, shortcut);
  SIZE(struct mjuiItemMulti_);
  FIELD(struct mjuiItemMulti_, nelem);
  FIELD(struct mjuiItemMulti_, name);
  SIZE(struct mjuiItemSlider_);
  FIELD(struct mjuiItemSlider_, range);
  FIELD(struct mjuiItemSlider_, divisions);
  SIZE(struct mjuiItemEdit_);
  FIELD(struct mjuiItemEdit_, nelem);
  FIELD(struct mjuiItemEdit_, range);
  SIZE(mjuiItem);
  FIELD(mjuiItem, type);
  FIELD(mjuiItem, name);
  FIELD(mjuiItem, state);
  FIELD(mjuiItem, pdata);
  FIELD(mjuiItem, sectionid);
  FIELD(mjuiItem, itemid);
  FIELD(mjuiItem, single);
  FIELD(mjuiItem, multi);
  FIELD(mjuiItem, slider);
  FIELD(mjuiItem, edit);
  FIELD(mjuiItem, rect);
  SIZE(mjuiSection);
  FIELD(mjuiSection, name);
  FIELD(mjuiSection, state);
  FIELD(mjuiSection, modifier);
  FIELD(mjuiSection, shortcut);
  FIELD(mjuiSection, nitem);
  FIELD(mjuiSection, item);
  FIELD(mjuiSection, rtitle);
  FIELD(mjuiSection, rcontent);
  SIZE(mjUI);
  FIELD(mjUI, spacing);
  FIELD(mjUI, color);
  FIELD(mjUI, predicate);
  FIELD(mjUI, userdata);
  FIELD(mjUI, rectid);
  FIELD(mjUI, auxid);
  FIELD(mjUI, radiocol);
  FIELD(mjUI, width);
  FIELD(mjUI, height);
  FIELD(mjUI, maxheight);
  FIELD(mjUI, scroll);
  FIELD(mjUI, mousesect);
  FIELD(mjUI, mouseitem);
  FIELD(mjUI, mousehelp);
  FIELD(mjUI, editsect);
  FIELD(mjUI, edititem);
  FIELD(mjUI, editcursor);
  FIELD(mjUI, editscroll);
  FIELD(mjUI, edittext);
  FIELD(mjUI, editchanged);
  FIELD(mjUI, nsect);
  FIELD(mjUI, sect);
  SIZE(mjuiDef);
  FIELD(mjuiDef, type);
  FIELD(mjuiDef, name);
  FIELD(mjuiDef, state);
  FIELD(mjuiDef, pdata);
  FIELD(mjuiDef, other);

  // enum values and numeric defines
#define E(name) printf("enum %s=%lld\n", #name, (long long)(name));
#define D(name) printf("define %s=%.17g\n", #name, (double)(name));
#include "layout_enums.h"
#undef E
#undef D
  return 0;
}
