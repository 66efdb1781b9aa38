/* A scene as a run sees it: its file parsed into the key struct
 * (src/scene/scene_load.c), its physical{} section mapped to model units
 * (src/mapping/mapping_scene.c), its own sections checked across keys
 * (src/scene/scene_validate.c), then each module's sections by the module
 * (its validate_scene, peloid/module.h).  Here, above the scene layer, so
 * that the scene knows neither the mapping nor the modules. */
#include "peloid/mapping.h"
#include "peloid/module.h"
#include "peloid/scene.h"

int pl_scene_validate(pl_scene_t *scene, pl_err_t *err)
{
    if (pl_mapping_scene_apply(scene, err)) return PL_ERR_INPUT; /* physical{} -> srd, fluid, box */
    const int rc = pl_scene_check_keys(scene, err);
    if (rc) return rc;
    for (int m = 0; pl_modules[m]; ++m) /* each module its own sections (peloid/module.h) */
        if (pl_modules[m]->validate_scene && pl_modules[m]->validate_scene(scene, err)) return PL_ERR_INPUT;
    return 0;
}

int pl_scene_load_calibrated(const char *path, unsigned flags, const pl_mapping_calibration_t *calib,
                             pl_scene_t *scene, pl_err_t *err)
{
    const int rc = pl_scene_parse_calibrated(path, flags, calib, scene, err);
    return rc ? rc : pl_scene_validate(scene, err);
}

int pl_scene_load_flags(const char *path, unsigned flags, pl_scene_t *scene, pl_err_t *err)
{
    return pl_scene_load_calibrated(path, flags, NULL, scene, err);
}

int pl_scene_load(const char *path, pl_scene_t *scene, pl_err_t *err)
{
    return pl_scene_load_flags(path, 0, scene, err);
}

int pl_scene_load_string(const char *text, const char *label, pl_scene_t *scene, pl_err_t *err)
{
    const int rc = pl_scene_parse_string(text, label, scene, err);
    return rc ? rc : pl_scene_validate(scene, err);
}
