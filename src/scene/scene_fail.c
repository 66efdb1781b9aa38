/* Where a scene key was given and the one-line error naming it
 * ("FILE:LINE: key 'K': ..."): the bottom of the scene modules, used by the
 * loader and by every module's validator (colloids, couplings, mapping), so
 * that validators report errors without calling back into the loader. */
#include <stdarg.h>
#include <stdio.h>

#include "peloid/scene.h"

int pl_scene_line_of(const pl_scene_t *scene, size_t offset)
{
    for (int i = scene->norigin - 1; i >= 0; --i)
        if (scene->origin[i].offset == offset) return scene->origin[i].line;
    return 0;
}

/* The file the key at `offset` was given in (the scene or an @include). */
static const char *file_of(const pl_scene_t *scene, size_t offset)
{
    for (int i = scene->norigin - 1; i >= 0; --i) {
        int f = scene->origin[i].file;
        if (scene->origin[i].offset == offset)
            return f > 0 && f < PL_SCENE_MAX_FILES ? scene->include_path[f - 1] : scene->path;
    }
    return scene->path;
}

int pl_scene_fail(const pl_scene_t *scene, pl_err_t *err, size_t offset, const char *key,
                  const char *fmt, ...)
{
    char what[768];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    int line = pl_scene_line_of(scene, offset);
    if (line > 0)
        return pl_err_set(err, PL_ERR_INPUT, "%s:%d: key '%s': %s", file_of(scene, offset), line, key, what);
    if (scene->mapping.enabled) /* not in the file: the unit mapping set it */
        return pl_err_set(err, PL_ERR_INPUT, "%s: key '%s' (derived from physical{}, see peloid params): %s",
                          scene->path, key, what);
    return pl_err_set(err, PL_ERR_INPUT, "%s: key '%s' (default): %s", scene->path, key, what);
}
