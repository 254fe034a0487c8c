/* cli_modes.c - `beamslider modes SCENE`: the modal data the core runs on. */
#include <stdio.h>
#include "cli.h"
#include "attached.h"
#include "out_text.h"
#include "scene_build.h"

const char cli_modes_synopsis[] = "beamslider modes SCENE.ini";
const char cli_modes_help[] =
    "  modal data: f_k [Hz], lambda_k, gamma_k, phi_k(4/7) per mode, and the mode-shape fit;\n"
    "  the first natural frequency with the slider rigidly attached at s (where it meets f_ex)\n";

int cli_modes(int argc, char **argv)
{
    static scene_file file;   /* static: large */
    static bs_scene scene;
    static scene_model model;
    char err[1024], name[SCENE_TEXT], path[SCENE_PATH];
    int k;

    if (argc != 1) {
        cli_error("modes takes exactly one scene file");
        return CLI_USAGE;
    }
    if (scene_read(argv[0], &file, &scene, &model, err, sizeof err) != 0) {
        cli_error("%s", err);
        return CLI_USAGE;
    }
    /* the table's comment lines stay one line each, whatever the names hold */
    snprintf(name, sizeof name, "%s", file.params.name);
    snprintf(path, sizeof path, "%s", argv[0]);
    printf("# scene %s (%s): %d modes, kappa = k_r L/EI = %.6g, b = %.6g mm, k_ax = %.6g N/m\n",
           out_text_one_line(name), out_text_one_line(path), model.modes.n, model.kappa, 1e3 * model.width,
           model.modes.k_axial_total);
    printf("# mode shapes: %d polynomial pieces of degree %d, relative error %.2g (phi), %.2g (slope)\n",
           model.fit.pieces, BS_SHAPE_COEFS - 1, model.fit.error_phi, model.fit.error_slope);
    printf("%-4s %14s %14s %14s %16s\n", "mode", "f_k[Hz]", "lambda_k", "gamma_k[kg^.5]",
           "phi_k(4/7)[kg^-.5]");
    for (k = 0; k < model.modes.n; ++k) {
        double phi, slope;
        modal_shape(&model.modes, k, 4.0 / 7.0, &phi, &slope);
        printf("%-4d %14.6f %14.9f %14.8f %16.8f\n", k + 1,
               model.modes.omega[k] / (2.0 * 3.14159265358979323846), model.modes.lambda[k],
               model.modes.gamma[k], phi);
    }
    printf("# slider rigidly attached at s: first natural frequency (Rayleigh-Ritz on these modes)\n");
    printf("%-6s %10s\n", "s", "f_1[Hz]");
    for (k = 2; k <= 20; ++k)
        printf("%-6.3f %10.2f\n", 0.025 * k, attached_frequency(&model.modes, &file.params, 0.025 * k));
    {
        const double s = attached_position(&model.modes, &file.params, file.params.frequency);
        if (s > 0.0)
            printf("# attached f_1 equals f_ex = %g Hz at s = %.4f\n", file.params.frequency, s);
        else
            printf("# attached f_1 does not reach f_ex = %g Hz between the clamp and the centre\n",
                   file.params.frequency);
    }
    return CLI_OK;
}
