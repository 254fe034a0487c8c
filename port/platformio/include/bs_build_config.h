/* bs_build_config.h of PlatformIO builds (port/platformio/README.md).
 *
 * The Makefile and CMake generate this header from
 * core/include/bs_build_config.h.in for each build. PlatformIO has no such
 * step, and a library's own flags do not reach the program's sources; but the
 * project's build_flags reach both the library and the program. So here the
 * configuration is what build_flags define, which both sides then see alike
 * (bs_sim_init still checks it: BS_E_BUILD on a mismatch):
 *
 *   -D BS_REAL_FLOAT=1                           float (0: double); required
 *   -D BS_SCENE_CONFIG='"configs/NAME.h"'        a compiled scene (optional;
 *                                                none: scenes given at run time)
 *   -D BS_WITH_SUBSPACE=0                        any switch of bs_config.h
 */
#ifndef BS_BUILD_CONFIG_H
#define BS_BUILD_CONFIG_H

#ifndef BS_REAL_FLOAT
#error "beamslider: add -D BS_REAL_FLOAT=1 (float) or -D BS_REAL_FLOAT=0 (double) to build_flags in platformio.ini"
#endif

#endif
