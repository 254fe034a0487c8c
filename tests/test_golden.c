/* test_golden.c - pinned state hashes: the same scene, stepped the same number
 * of times, must end in the same bits (Box2D pins its determinism hashes the
 * same way). A change that moves them changes results: it must update the
 * values below in the same commit and say why (and re-run docs/accuracy.md).
 *
 * The values were produced by this test's own runs at the commit that pinned
 * them; they are regression anchors, not an independent oracle (that is
 * tests/reference). They hold for any IEEE-754 machine and optimisation level,
 * since the build keeps fused multiply-add off. */
#include "support.h"

static scene_file file;
static bs_scene scene;
static scene_model model;
static bs_sim sim;

typedef struct golden {
    const char *scene_path;
    long steps;
    uint32_t hash_double, hash_float;
} golden;

/* Moved in 0.8.0 by the step's redesign (docs/CHANGELOG.md): constants
 * pre-multiplied by dt, the contact rows formed as combinations of phi and
 * phi' (products summed in another order), cos alpha from a series, the pair
 * solve by Cramer's rule from the last step's modes; the slow dynamics were
 * compared with 0.7.0's over 512-run ensembles (docs/baseline.md). */
static const golden pinned[] = {
    { "configs/fig6.ini", 20000, 0xeb14c821u, 0x91964252u },
    { "configs/fig6.ini", 100000, 0x33427528u, 0x4acd4e32u },
    { "configs/fig6_1mode.ini", 20000, 0x8f3bcc30u, 0x9ed4779au },
    { "configs/fig6_1mode.ini", 100000, 0x76d9a3f7u, 0x397bb183u },
};

static void test_pinned_state_hashes(void **state)
{
    size_t i;
    int mismatches = 0;
    (void)state;
    for (i = 0; i < sizeof pinned / sizeof pinned[0]; ++i) {
        const golden *g = &pinned[i];
        const uint32_t expected = BS_REAL_FLOAT ? g->hash_float : g->hash_double;
        uint32_t hash;
        long step;
        support_load(g->scene_path, &file, &scene, &model);
        assert_int_equal(bs_sim_init(&sim, &scene, BS_MODEL_FREE, (bs_real)file.params.s0), BS_OK);
        for (step = 0; step < g->steps; ++step)
            assert_int_equal(bs_sim_step(&sim), BS_OK);
        hash = bs_sim_hash(&sim);
        print_message("%s, %ld steps, %s: hash %08x (pinned %08x)%s\n", g->scene_path, g->steps,
                      BS_REAL_NAME, hash, expected, hash == expected ? "" : ": DIFFERENT");
        mismatches += hash != expected;
    }
    assert_int_equal(mismatches, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pinned_state_hashes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
