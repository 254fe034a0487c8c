/* bs_version.c - the library's version, its build configuration and the
 * texts of its statuses. */
#include "beamslider.h"
#include "bs_sim_internal.h"

const char *bs_version(void)
{
    return BS_VERSION_STRING;
}

/* The program's view (tag and sizes, passed by the macros of beamslider.h)
 * against this library's own, as compiled here. */
bs_status bs_build_matches(uint32_t tag, size_t sim_size, size_t scene_size)
{
    return tag == BS_BUILD_TAG && sim_size == sizeof(bs_sim) && scene_size == sizeof(bs_scene)
               ? BS_OK
               : BS_E_BUILD;
}

bs_status bs_build_check_(uint32_t tag, size_t sim_size, size_t scene_size)
{
    return bs_build_matches(tag, sim_size, scene_size);
}

const char *bs_status_text(bs_status status)
{
    switch (status) {
    case BS_OK: return "ok";
    case BS_E_NULL: return "null pointer";
    case BS_E_SCENE: return "scene field out of range";
    case BS_E_ARGUMENT: return "argument out of range";
    case BS_E_UNSTABLE: return "stability limit omega*dt < 2 of the explicitly integrated stiffness violated";
    case BS_E_NONFINITE: return "state became NaN or infinite";
    case BS_E_ESCAPED: return "the slider left the beam (a contact did not hold)";
    case BS_E_BUILD: return "program and library built with different configurations (precision, sizes, "
                            "switches or version)";
    case BS_E_UNINITIALISED: return "simulation not initialised (or its initialisation failed)";
    case BS_E_CHECKPOINT_SIZE: return "checkpoint buffer too small, or a checkpoint of another size";
    case BS_E_CHECKPOINT_DAMAGED: return "not a checkpoint, or a damaged one (magic, byte order or checksum)";
    case BS_E_CHECKPOINT_BUILD: return "checkpoint from another version or build (precision, switches, modes)";
    case BS_E_CHECKPOINT_SCENE: return "checkpoint from another scene, or of a state this simulation cannot take";
    }
    return "unknown status";
}
