/* HDF5 helpers without time stamps, and the H5MD header (H5MD 1.1). */
#include "peloid/h5.h"

#include <string.h>

hid_t pl_h5_group(hid_t parent, const char *name)
{
    hid_t gcpl = H5Pcreate(H5P_GROUP_CREATE);
    H5Pset_obj_track_times(gcpl, 0);
    hid_t g = H5Gcreate2(parent, name, H5P_DEFAULT, gcpl, H5P_DEFAULT);
    H5Pclose(gcpl);
    return g;
}

void pl_h5_attr_str(hid_t obj, const char *name, const char *value)
{
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, strlen(value) + 1);
    hid_t sp = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(obj, name, t, sp, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, t, value);
    H5Aclose(a);
    H5Sclose(sp);
    H5Tclose(t);
}

int pl_h5_write(hid_t parent, const char *name, hid_t type, int rank, const hsize_t *dims, const void *data)
{
    hid_t sp = rank > 0 ? H5Screate_simple(rank, dims, NULL) : H5Screate(H5S_SCALAR);
    hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_obj_track_times(dcpl, 0);
    hid_t ds = H5Dcreate2(parent, name, type, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    H5Pclose(dcpl);
    herr_t st = ds >= 0 ? H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) : -1;
    if (ds >= 0) H5Dclose(ds);
    H5Sclose(sp);
    return st < 0 ? -1 : 0;
}

void pl_h5_h5md_header(hid_t file)
{
    hid_t h5md = pl_h5_group(file, "h5md");
    int version[2] = {1, 1};
    hsize_t two = 2;
    hid_t sp = H5Screate_simple(1, &two, NULL);
    hid_t a = H5Acreate2(h5md, "version", H5T_NATIVE_INT, sp, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_INT, version);
    H5Aclose(a);
    H5Sclose(sp);
    hid_t g = pl_h5_group(h5md, "author");
    pl_h5_attr_str(g, "name", "peloid");
    H5Gclose(g);
    g = pl_h5_group(h5md, "creator");
    pl_h5_attr_str(g, "name", "peloid");
    pl_h5_attr_str(g, "version", PL_GIT_REV);
    H5Gclose(g);
    H5Gclose(h5md);
}
