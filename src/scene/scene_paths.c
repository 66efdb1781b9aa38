/* Where the files a scene names are opened: colloids.init_file and
 * colloids.table_file, relative to the scene file's directory unless
 * absolute.  The scene's own concern, so that the colloids (which read the
 * files), the run (which copies them into its folder) and the checkpoint's
 * fingerprint (which hashes the table's bytes) resolve them alike. */
#include "peloid/io.h"
#include "peloid/scene.h"

void pl_scene_init_file_path(const pl_scene_t *scene, char *buf, size_t n)
{
    pl_path_beside(buf, n, scene->path, scene->colloids.init_file);
}

void pl_scene_table_file_path(const pl_scene_t *scene, char *buf, size_t n)
{
    pl_path_beside(buf, n, scene->path, scene->colloids.table_file);
}
