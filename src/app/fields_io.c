/* Time-averaged fluid fields on the (unshifted) cell grid, as H5MD 1.1
 * time-dependent elements, and an XDMF sidecar so that ParaView / VisIt open
 * them:
 *   /h5md                 version, author, creator, modules/units
 *   /observables/fluid_density   value[T][Lz][Ly][Lx]    (particles / a0^3)
 *   /observables/fluid_velocity  value[T][Lz][Ly][Lx][3] (a0 / t0; mass-weighted
 *        mean velocity, 0 where a cell was always empty)
 *   each with step[T], time[T] (t0) and the grid as attributes: origin and
 *   spacing [x, y, z] in a0 of the cell corners, the values at cell centres;
 *   /observables attributes boundary_x/y/z (periodic, or noslip / slip walls
 *   at 0 and L: Hecht Sec. VIII.A), samples, average_start.
 * One frame (T = 1): the average over the run, stamped with its last step.
 * Model units, stated in `model_unit` attributes (as in a model colloids.h5).
 * A physical scene adds a0_m and t0_s to /observables and, in each group,
 * the real system's values for ParaView's scale: value_si (um-3, um s-1),
 * time_si (s), each with `unit` and `to_si` (x_si = x * to_si), and the
 * attributes origin_si and spacing_si (um).
 * The XDMF file (fields.xdmf, next to fields.h5) describes a 3DCoRectMesh of
 * (Lz+1) x (Ly+1) x (Lx+1) nodes with cell-centred attributes read from
 * fields.h5 by hyperslab, one grid per frame in a temporal collection: in
 * um, s and value_si for a physical scene, else in a0, t0 and value.
 * Both are written to PATH.tmp and renamed. */
#include <errno.h>
#include <hdf5.h>
#include <libgen.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "peloid/h5.h"
#include "peloid/io.h"
#include "peloid/mapping.h"
#include "peloid/writer.h"

/* Dataset `name` of g: d[0..n) * f with attributes unit and to_si. */
static int put_si(hid_t g, const char *name, int rank, const hsize_t *dims, const double *d, size_t n, double f,
                  const char *unit)
{
    double *x = malloc((n ? n : 1) * sizeof *x);
    if (!x) return -1;
    for (size_t k = 0; k < n; ++k) x[k] = d[k] * f;
    int bad = pl_h5_write(g, name, H5T_NATIVE_DOUBLE, rank, dims, x);
    free(x);
    hid_t ds = bad ? -1 : H5Dopen2(g, name, H5P_DEFAULT);
    bad |= ds < 0 || pl_h5_attr_vlstr(ds, "unit", unit) || pl_h5_attr_doubles(ds, "to_si", &f, 1);
    if (ds >= 0 && H5Dclose(ds) < 0) bad = 1;
    return bad ? -1 : 0;
}

/* The real system's side of a field for a physical scene (m: its mapping):
 * the value times f in unit_si, time in s, the grid in um. */
typedef struct {
    const pl_mapping_t *m;
    double f;
    const char *unit_si;
} field_si_t;

static int observable(hid_t obs, const char *name, int rank, const hsize_t *dims, const double *d,
                      long long step, double time, const char *unit, const field_si_t *si)
{
    hid_t g = pl_h5_group(obs, name);
    if (g < 0) return -1;
    hsize_t one = 1;
    int bad = pl_h5_write(g, "value", H5T_NATIVE_DOUBLE, rank, dims, d);
    bad |= pl_h5_write(g, "step", H5T_NATIVE_LLONG, 1, &one, &step);
    bad |= pl_h5_write(g, "time", H5T_NATIVE_DOUBLE, 1, &one, &time);
    const double origin[3] = {0.0, 0.0, 0.0}, spacing[3] = {1.0, 1.0, 1.0};
    bad |= pl_h5_attr_doubles(g, "origin", origin, 3) || pl_h5_attr_doubles(g, "spacing", spacing, 3);
    bad |= pl_h5_attr_vlstr(g, "grid_unit", "a0");
    hid_t v = H5Dopen2(g, "value", H5P_DEFAULT), t = H5Dopen2(g, "time", H5P_DEFAULT);
    bad |= v < 0 || t < 0 || pl_h5_attr_vlstr(v, "model_unit", unit) || pl_h5_attr_vlstr(t, "model_unit", "t0");
    if (v >= 0 && H5Dclose(v) < 0) bad = 1;
    if (t >= 0 && H5Dclose(t) < 0) bad = 1;
    if (si->m) {
        size_t n = 1;
        for (int k = 0; k < rank; ++k) n *= (size_t)dims[k];
        const double um = si->m->a0 * 1e6, o_si[3] = {0.0, 0.0, 0.0}, s_si[3] = {um, um, um};
        bad |= put_si(g, "value_si", rank, dims, d, n, si->f, si->unit_si) ||
               put_si(g, "time_si", 1, &one, &time, 1, si->m->t0, "s") ||
               pl_h5_attr_doubles(g, "origin_si", o_si, 3) || pl_h5_attr_doubles(g, "spacing_si", s_si, 3) ||
               pl_h5_attr_vlstr(g, "grid_unit_si", "um");
    }
    if (H5Gclose(g) < 0) bad = 1;
    return bad ? -1 : 0;
}

/* fields.xdmf beside fields.h5 (its name relative, so the pair can move);
 * m: a physical scene's mapping (the grid in um, time in s, value_si), or
 * NULL (model units). */
static int write_xdmf(const char *h5path, const int *L, long long step, double time, const pl_mapping_t *m,
                      pl_err_t *err)
{
    char xpath[PATH_MAX], tmp[PATH_MAX + 8], base[PATH_MAX];
    snprintf(xpath, sizeof xpath, "%s", h5path);
    char *dot = strrchr(xpath, '.');
    if (dot) *dot = '\0';
    strncat(xpath, ".xdmf", sizeof xpath - strlen(xpath) - 1);
    snprintf(base, sizeof base, "%s", h5path);
    const char *h5name = basename(base);
    FILE *f = pl_file_begin(xpath, tmp, sizeof tmp, err);
    if (!f) return PL_ERR_IO;
    static const char *const names[2] = {"fluid_density", "fluid_velocity"};
    fprintf(f, "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n"
               " <Domain>\n  <Grid Name=\"fields\" GridType=\"Collection\" CollectionType=\"Temporal\">\n");
    const double h = m ? m->a0 * 1e6 : 1.0;
    const char *value = m ? "value_si" : "value";
    fprintf(f, "   <Grid Name=\"step %lld\" GridType=\"Uniform\">\n    <Time Value=\"%.17g\"/>\n", step,
            m ? time * m->t0 : time);
    fprintf(f, "    <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"%d %d %d\"/>\n", L[2] + 1, L[1] + 1,
            L[0] + 1);
    fprintf(f, "    <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
               "     <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">0 0 0</DataItem>\n"
               "     <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">%.17g %.17g "
               "%.17g</DataItem>\n"
               "    </Geometry>\n", h, h, h);
    for (int k = 0; k < 2; ++k) {
        const char *w = k ? " 3" : "", *s = k ? " 0" : "", *one = k ? " 1" : "";
        fprintf(f, "    <Attribute Name=\"%s\" AttributeType=\"%s\" Center=\"Cell\">\n", names[k],
                k ? "Vector" : "Scalar");
        fprintf(f, "     <DataItem ItemType=\"HyperSlab\" Dimensions=\"%d %d %d%s\" Type=\"HyperSlab\">\n", L[2],
                L[1], L[0], w);
        fprintf(f, "      <DataItem Dimensions=\"3 %d\" Format=\"XML\">0 0 0 0%s 1 1 1 1%s 1 %d %d %d%s</DataItem>\n",
                k ? 5 : 4, s, one, L[2], L[1], L[0], w);
        fprintf(f, "      <DataItem Dimensions=\"1 %d %d %d%s\" NumberType=\"Float\" Precision=\"8\" "
                   "Format=\"HDF\">%s:/observables/%s/%s</DataItem>\n", L[2], L[1], L[0], w, h5name, names[k], value);
        fprintf(f, "     </DataItem>\n    </Attribute>\n");
    }
    fprintf(f, "   </Grid>\n  </Grid>\n </Domain>\n</Xdmf>\n");
    return pl_file_commit(f, tmp, xpath, err);
}

int pl_fields_write(const pl_sim_t *sim, const char *path, pl_err_t *err)
{
    const pl_scene_t *sc = &sim->scene;
    const int *L = sc->box.cells;
    size_t L3 = (size_t)L[0] * (size_t)L[1] * (size_t)L[2];
    double *rho = malloc(L3 * sizeof *rho), *vel = malloc(3 * L3 * sizeof *vel);
    if (!rho || !vel) {
        free(rho);
        free(vel);
        return pl_err_set(err, PL_ERR_NOMEM, "out of memory writing fields");
    }
    const double inv_fixed = 1.0 / (double)(1LL << PL_FIELD_FIXED_SHIFT);
    long long samples;
    const int64_t *acc = pl_srd_fields(sim->srd, &samples);
    double ns = samples > 0 ? (double)samples : 1.0;
    for (size_t c = 0; c < L3; ++c) {
        int64_t cnt = acc[c];
        rho[c] = (double)cnt / ns;
        for (int d = 0; d < 3; ++d)
            vel[3 * c + (size_t)d] =
                cnt > 0 ? (double)acc[(size_t)(d + 1) * L3 + c] * inv_fixed / (double)cnt : 0.0;
    }
    char tmp[PATH_MAX + 8], why[256];
    pl_atomic_tmp(path, tmp, sizeof tmp);
    pl_h5_quiet();
    errno = 0;
    hid_t f = H5Fcreate(tmp, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (f < 0) {
        pl_h5_error_text(why, sizeof why);
        free(rho);
        free(vel);
        return pl_err_set(err, PL_ERR_IO, "%s: cannot create HDF5 file: %s", tmp, why);
    }
    int bad = pl_h5_h5md_header(f);
    hid_t obs = pl_h5_group(f, "observables");
    double time = (double)sim->step * sc->srd.dt;
    if (obs >= 0) {
        bad |= pl_h5_attr_str(obs, "layout", "value[time][z][y][x] on the unshifted cell grid, cell size a0 = 1");
        int walls[3];
        pl_scene_box_walls(&sc->box, walls);
        static const char *const bname[3] = {"boundary_x", "boundary_y", "boundary_z"};
        for (int d = 0; d < 3; ++d) bad |= pl_h5_attr_str(obs, bname[d], pl_scene_boundary_name(walls[d]));
        hsize_t dims[5] = {1, (hsize_t)L[2], (hsize_t)L[1], (hsize_t)L[0], 3};
        const pl_mapping_t *m = sc->mapping.enabled ? &sc->mapping.map : NULL;
        const double um = m ? m->a0 * 1e6 : 1.0;
        const field_si_t rho_si = {m, 1.0 / (um * um * um), "um-3"}, vel_si = {m, m ? um / m->t0 : 1.0, "um s-1"};
        bad |= observable(obs, "fluid_density", 4, dims, rho, sim->step, time, "a0-3", &rho_si);
        bad |= observable(obs, "fluid_velocity", 5, dims, vel, sim->step, time, "a0 t0-1", &vel_si);
        if (sc->mapping.enabled)
            bad |= pl_h5_attr_doubles(obs, "a0_m", &sc->mapping.map.a0, 1) ||
                   pl_h5_attr_doubles(obs, "t0_s", &sc->mapping.map.t0, 1);
        long long start = sc->output.fields_start;
        bad |= pl_h5_write(obs, "samples", H5T_NATIVE_LLONG, 0, NULL, &samples);
        bad |= pl_h5_write(obs, "average_start", H5T_NATIVE_LLONG, 0, NULL, &start);
        if (H5Gclose(obs) < 0) bad = 1;
    } else {
        bad = 1;
    }
    free(rho);
    free(vel);
    if (bad) pl_h5_error_text(why, sizeof why); /* before H5Fclose clears the stack */
    if (H5Fclose(f) < 0 && !bad) {
        pl_h5_error_text(why, sizeof why);
        bad = 1;
    }
    if (bad) {
        unlink(tmp);
        return pl_err_set(err, PL_ERR_IO, "%s: writing fields failed: %s", tmp, why);
    }
    if (pl_atomic_commit(tmp, path, err)) return PL_ERR_IO;
    return write_xdmf(path, L, sim->step, time, sc->mapping.enabled ? &sc->mapping.map : NULL, err);
}
