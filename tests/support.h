/* support.h - shared helpers of the CMocka tests. */
#ifndef SUPPORT_H
#define SUPPORT_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "beamslider.h"
#include "bs_monitor.h"
#include "scene_build.h"

/* Machine epsilon of the precision under test. */
#define SUPPORT_EPS ((double)BS_REAL_EPS)

/* Loads and builds a scene file; fails the test on any error. */
void support_load(const char *path, scene_file *file, bs_scene *scene, scene_model *model);

/* Rebuilds scene from file->params after a test changed them; fails on error. */
void support_build(scene_file *file, bs_scene *scene, scene_model *model);

/* The last step's contact report; fails the test if the sim refuses it. */
bs_step_report support_report(const bs_sim *sim);

/* Reproducible white Gaussian noise of unit variance (xorshift64*, Box-Muller):
 * support_gaussian_seed starts the sequence again. */
void support_gaussian_seed(uint64_t seed);
double support_gaussian(void);

/* A new folder /tmp/NAME.XXXXXX, its path in dir (size bytes): 0, or -1. */
int support_tmp_dir(char *dir, size_t size, const char *name);

/* Removes folder dir and the files in it (a test's folder has no
 * sub-folders): 0, or -1 if a file or the folder could not be removed. */
int support_tmp_dir_remove(const char *dir);

/* Marks the calling test skipped unless BS_TEST_LONG is set in the
 * environment: a case too slow for `make test`'s CPU budget, which `make
 * test-long` runs (tests-long-cases, in the Makefile). */
void support_long_only(void);

/* Fails unless |actual - expected| <= abs_tol + rel_tol |expected|, printing
 * what was compared, both values and the tolerance. */
#define assert_close(what, actual, expected, abs_tol, rel_tol) \
    support_assert_close(what, (double)(actual), (double)(expected), abs_tol, rel_tol, __FILE__, __LINE__)
void support_assert_close(const char *what, double actual, double expected, double abs_tol,
                          double rel_tol, const char *file, int line);

#endif
