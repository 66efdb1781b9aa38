/* Scene text: the scene file with its @include files expanded into one
 * buffer, which libconfig then parses as a string, and a map from each line
 * of that buffer back to (file, line).
 *
 * The expansion is done here rather than by libconfig 1.5, which resolves an
 * @include against one global directory (the working directory by default),
 * accepts any absolute path and reports "/" as a bare scanner failure.  Here
 * an @include is resolved relative to the including file, must stay inside
 * the scene's directory tree (unless --allow-include-anywhere), must be a
 * regular file, and every error names the file and line of the directive.
 * The same pass refuses strings that do not close on their line (an
 * unterminated string is reported where it starts, not where the file ends).
 *
 * libconfig 1.5 silently wraps integers written without the L suffix to 32
 * bits (4294967296 reads as 0); pl_scene_text_integer gives the value as
 * written instead, so that the loader can range-check it in 64 bits. */
#include "scene_text.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

enum { MAX_DEPTH = 8 };

static int grow(void **p, size_t *cap, size_t need, size_t elem)
{
    if (need <= *cap) return 0;
    size_t n = *cap ? *cap : 64;
    while (n < need) n *= 2;
    void *q = realloc(*p, n * elem);
    if (!q) return -1;
    *p = q;
    *cap = n;
    return 0;
}

static int nomem(pl_err_t *err) { return pl_err_set(err, PL_ERR_NOMEM, "out of memory reading the scene"); }

/* Appends one line (without its newline) mapped to (file, line). */
static int emit(pl_scene_text_t *t, const char *s, size_t n, int file, int line, pl_err_t *err)
{
    size_t cl = t->cap_lines;
    if (grow((void **)&t->text, &t->cap, t->len + n + 2, 1) ||
        grow((void **)&t->file_of, &cl, t->nlines + 1, sizeof(int)) ||
        grow((void **)&t->line_of, &t->cap_lines, t->nlines + 1, sizeof(int)))
        return nomem(err);
    memcpy(t->text + t->len, s, n);
    t->len += n;
    t->text[t->len++] = '\n';
    t->text[t->len] = '\0';
    t->file_of[t->nlines] = file;
    t->line_of[t->nlines] = line;
    t->nlines++;
    return 0;
}

static int ident(int ch) { return isalnum(ch) || ch == '_' || ch == '-' || ch == '*'; }

/* Name of the setting whose value starts at `q` on the line [s, q). */
static void key_before(const char *s, const char *q, char *buf, size_t n)
{
    const char *e = q;
    while (e > s && (e[-1] == ' ' || e[-1] == '\t')) --e;
    if (e > s && (e[-1] == '=' || e[-1] == ':')) --e;
    while (e > s && (e[-1] == ' ' || e[-1] == '\t')) --e;
    const char *b = e;
    while (b > s && ident((unsigned char)b[-1])) --b;
    snprintf(buf, n, "%.*s", (int)(e - b), b);
}

static int add_file(pl_scene_text_t *t, const char *name, const char *data, size_t n, int depth,
                    pl_err_t *err);

/* Reads a whole regular file into a NUL-terminated buffer. */
static char *slurp(const char *path, size_t *n, int *eno)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        *eno = errno;
        return NULL;
    }
    char *buf = NULL;
    size_t cap = 0, len = 0;
    for (;;) {
        if (grow((void **)&buf, &cap, len + 4096 + 1, 1)) {
            *eno = ENOMEM;
            break;
        }
        size_t got = fread(buf + len, 1, cap - len - 1, f);
        len += got;
        if (got == 0) break;
    }
    if (ferror(f) || !buf) {
        *eno = ferror(f) ? EIO : *eno;
        fclose(f);
        free(buf);
        return NULL;
    }
    fclose(f);
    buf[len] = '\0';
    *n = len;
    return buf;
}

/* The @include directive on line `line` of file `fi`: `p` points just after
 * "@include", `eol` at the end of the line. */
static int include(pl_scene_text_t *t, int fi, int line, const char *p, const char *eol, int depth,
                   pl_err_t *err)
{
    const char *file = t->files[fi];
    char rel[PATH_MAX + 1];
    size_t n = 0;
    while (p < eol && (*p == ' ' || *p == '\t')) ++p;
    if (p >= eol || *p != '"')
        return pl_err_set(err, PL_ERR_INPUT, "%s:%d: @include: expected a quoted file name; allowed: "
                          "@include \"FILE\"", file, line);
    for (++p; p < eol && *p != '"'; ++p) {
        if (*p == '\\' && p + 1 < eol) ++p;
        if (n >= PATH_MAX)
            return pl_err_set(err, PL_ERR_INPUT, "%s:%d: @include: file name longer than %d characters",
                              file, line, PATH_MAX);
        rel[n++] = *p;
    }
    rel[n] = '\0';
    if (p >= eol)
        return pl_err_set(err, PL_ERR_INPUT, "%s:%d: @include \"%.200s: unterminated file name; allowed: "
                          "@include \"FILE\" on one line", file, line, rel);
    for (++p; p < eol && (*p == ' ' || *p == '\t' || *p == '\r'); ++p) {}
    if (p < eol && *p != '#' && strncmp(p, "//", 2))
        return pl_err_set(err, PL_ERR_INPUT, "%s:%d: @include \"%.200s\": unexpected text after the file "
                          "name; allowed: nothing or a comment", file, line, rel);
    if (!rel[0])
        return pl_err_set(err, PL_ERR_INPUT, "%s:%d: @include \"\": empty file name", file, line);
    /* relative to the including file's directory */
    char full[PATH_MAX + 1];
    const char *slash = strrchr(file, '/');
    int dl = rel[0] == '/' || !slash ? 0 : (int)(slash - file) + 1;
    if ((size_t)dl + n > PATH_MAX)
        return pl_err_set(err, PL_ERR_INPUT, "%s:%d: @include \"%.200s\": path longer than %d characters",
                          file, line, rel, PATH_MAX);
    memcpy(full, file, (size_t)dl); /* dl + n <= PATH_MAX checked above */
    memcpy(full + dl, rel, n + 1);
    struct stat st;
    if (stat(full, &st))
        return pl_err_set(err, PL_ERR_INPUT, "%s:%d: @include \"%.200s\": cannot open %.300s: %s", file, line,
                          rel, full, strerror(errno));
    if (!S_ISREG(st.st_mode))
        return pl_err_set(err, PL_ERR_INPUT, "%s:%d: @include \"%.200s\": %s; allowed: a scene file", file,
                          line, rel, S_ISDIR(st.st_mode) ? "is a directory" : "is not a regular file");
    char real[PATH_MAX];
    if (!realpath(full, real))
        return pl_err_set(err, PL_ERR_INPUT, "%s:%d: @include \"%.200s\": %s", file, line, rel, strerror(errno));
    size_t rl = strlen(t->root);
    if (!t->anywhere && !(strncmp(real, t->root, rl) == 0 && (real[rl] == '/' || (rl == 1 && t->root[0] == '/'))))
        return pl_err_set(err, PL_ERR_INPUT, "%s:%d: @include \"%.200s\": %.300s is outside the scene's "
                          "directory %.300s; allowed: files under it (or --allow-include-anywhere)",
                          file, line, rel, real, t->root);
    if (depth + 1 >= MAX_DEPTH)
        return pl_err_set(err, PL_ERR_INPUT, "%s:%d: @include \"%.200s\": nested more than %d deep (an include "
                          "cycle?)", file, line, rel, MAX_DEPTH - 1);
    if (t->nfiles >= PL_SCENE_TEXT_MAX_FILES)
        return pl_err_set(err, PL_ERR_INPUT, "%s:%d: @include \"%.200s\": more than %d included files; "
                          "allowed: at most %d", file, line, rel, PL_SCENE_TEXT_MAX_FILES - 1,
                          PL_SCENE_TEXT_MAX_FILES - 1);
    size_t len;
    int eno = 0;
    char *data = slurp(full, &len, &eno);
    if (!data)
        return pl_err_set(err, PL_ERR_INPUT, "%s:%d: @include \"%.200s\": cannot read: %s", file, line, rel,
                          strerror(eno));
    int rc = add_file(t, full, data, len, depth + 1, err);
    free(data);
    return rc;
}

static int add_file(pl_scene_text_t *t, const char *name, const char *data, size_t n, int depth,
                    pl_err_t *err)
{
    int fi = t->nfiles;
    if (!(t->files[fi] = strdup(name))) return nomem(err);
    t->nfiles++;
    if (memchr(data, '\0', n))
        return pl_err_set(err, PL_ERR_INPUT, "%s: contains a NUL byte; allowed: a text file", name);
    int in_comment = 0, comment_line = 0;
    int line = 0;
    for (const char *s = data; s < data + n;) {
        const char *eol = memchr(s, '\n', (size_t)(data + n - s));
        if (!eol) eol = data + n;
        ++line;
        const char *p = s;
        while (p < eol && (*p == ' ' || *p == '\t')) ++p;
        if (!in_comment && eol - p >= 8 && !strncmp(p, "@include", 8)) {
            int rc = include(t, fi, line, p + 8, eol, depth, err);
            if (rc) return rc;
        } else {
            for (p = s; p < eol; ++p) { /* track comments and strings */
                if (in_comment) {
                    if (p[0] == '*' && p + 1 < eol && p[1] == '/') {
                        in_comment = 0;
                        ++p;
                    }
                } else if (*p == '#' || (p[0] == '/' && p + 1 < eol && p[1] == '/')) {
                    break;
                } else if (p[0] == '/' && p + 1 < eol && p[1] == '*') {
                    in_comment = 1;
                    comment_line = line;
                    ++p;
                } else if (*p == '"') {
                    const char *q = p + 1;
                    while (q < eol && *q != '"') q += (*q == '\\' && q + 1 < eol) ? 2 : 1;
                    if (q >= eol) {
                        char key[128];
                        key_before(s, p, key, sizeof key);
                        int shown = eol - p > 40 ? 40 : (int)(eol - p);
                        if (key[0])
                            return pl_err_set(err, PL_ERR_INPUT, "%s:%d: key '%s': unterminated string (%.*s); "
                                              "allowed: a string closed by '\"' on the line it starts",
                                              name, line, key, shown, p);
                        return pl_err_set(err, PL_ERR_INPUT, "%s:%d: unterminated string (%.*s); allowed: a "
                                          "string closed by '\"' on the line it starts", name, line, shown, p);
                    }
                    p = q;
                }
            }
            int rc = emit(t, s, (size_t)(eol - s), fi, line, err);
            if (rc) return rc;
        }
        s = eol + 1;
    }
    if (in_comment)
        return pl_err_set(err, PL_ERR_INPUT, "%s:%d: unterminated comment '/*'; allowed: a comment closed "
                          "by '*/'", name, comment_line);
    return 0;
}

int pl_scene_text_read(pl_scene_text_t *t, const char *path, int anywhere, pl_err_t *err)
{
    memset(t, 0, sizeof *t);
    t->anywhere = anywhere;
    struct stat st;
    if (strlen(path) >= PATH_MAX)
        return pl_err_set(err, PL_ERR_INPUT, "%.200s...: scene path longer than %d characters", path,
                          PATH_MAX - 1);
    if (stat(path, &st))
        return pl_err_set(err, PL_ERR_INPUT, "%s: cannot open scene file: %s", path, strerror(errno));
    if (!S_ISREG(st.st_mode))
        return pl_err_set(err, PL_ERR_INPUT, "%s: cannot read scene file: %s", path,
                          S_ISDIR(st.st_mode) ? "is a directory" : "not a regular file");
    char dir[PATH_MAX];
    const char *slash = strrchr(path, '/');
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - path) + (slash == path) : 1, slash ? path : ".");
    if (!realpath(dir, t->root))
        return pl_err_set(err, PL_ERR_INPUT, "%s: cannot resolve the scene's directory: %s", path,
                          strerror(errno));
    size_t n;
    int eno = 0;
    char *data = slurp(path, &n, &eno);
    if (!data) return pl_err_set(err, PL_ERR_INPUT, "%s: cannot read scene file: %s", path, strerror(eno));
    int rc = add_file(t, path, data, n, 0, err);
    free(data);
    if (!rc && !t->text) rc = emit(t, "", 0, 0, 1, err);
    return rc;
}

int pl_scene_text_string(pl_scene_text_t *t, const char *text, const char *label, pl_err_t *err)
{
    memset(t, 0, sizeof *t);
    if (!realpath(".", t->root)) return pl_err_set(err, PL_ERR_INPUT, "%s: cannot resolve '.'", label);
    int rc = add_file(t, label, text, strlen(text), 0, err);
    if (!rc && !t->text) rc = emit(t, "", 0, 0, 1, err);
    return rc;
}

void pl_scene_text_free(pl_scene_text_t *t)
{
    free(t->text);
    free(t->file_of);
    free(t->line_of);
    for (int i = 0; i < t->nfiles; ++i) free(t->files[i]);
    memset(t, 0, sizeof *t);
}

void pl_scene_text_line(const pl_scene_text_t *t, int line, char *buf, size_t n)
{
    buf[0] = '\0';
    if (line < 1 || (size_t)line > t->nlines) return;
    const char *s = t->text;
    for (int l = 1; l < line; ++l) s = strchr(s, '\n') + 1;
    while (*s == ' ' || *s == '\t') ++s;
    size_t len = strcspn(s, "\r\n");
    if (len + 1 > n) len = n - 1;
    memcpy(buf, s, len);
    buf[len] = '\0';
}

int pl_scene_text_where(const pl_scene_text_t *t, int line, int *file_line)
{
    if (line < 1 || (size_t)line > t->nlines) {
        *file_line = line;
        return 0;
    }
    *file_line = t->line_of[line - 1];
    return t->file_of[line - 1];
}

/* Parses a libconfig integer literal (decimal or 0x hex, optional L/LL). */
static int parse_literal(const char *lit, long long *out)
{
    const char *p = lit;
    int neg = 0;
    if (*p == '+' || *p == '-') neg = *p++ == '-';
    char *end;
    errno = 0;
    if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X')) {
        unsigned long long u = strtoull(p + 2, &end, 16);
        if (end == p + 2) return -1;
        if (errno == ERANGE || u > (unsigned long long)LLONG_MAX) return 1;
        *out = neg ? -(long long)u : (long long)u;
    } else {
        long long v = strtoll(lit, &end, 10);
        if (end == lit) return -1;
        if (errno == ERANGE) return 1;
        *out = v;
    }
    while (*end == 'L' || *end == 'l') ++end;
    return *end ? -1 : 0;
}

static const char *read_token(const char *p, char *lit, size_t nlit)
{
    size_t k = 0;
    while ((isalnum((unsigned char)*p) || *p == '+' || *p == '-' || *p == '.') && k + 1 < nlit) lit[k++] = *p++;
    lit[k] = '\0';
    return p;
}

static const char *skip_space(const char *p)
{
    while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') ++p;
    return p;
}

/* Start of the value of setting `name` (element `elem`, -1: a scalar) at
 * its k-th occurrence (0-based) on expanded line `line`, or NULL. */
static const char *value_at(const pl_scene_text_t *t, int line, const char *name, int elem, int k)
{
    if (line < 1 || (size_t)line > t->nlines || !name || !*name) return NULL;
    const char *s = t->text;
    for (int l = 1; l < line; ++l) s = strchr(s, '\n') + 1;
    const char *eol = strchr(s, '\n');
    size_t nl = strlen(name);
    for (const char *q = s; q < eol && (q = strstr(q, name)) && q < eol; q += nl) {
        if ((q > s && ident((unsigned char)q[-1])) || ident((unsigned char)q[nl])) continue;
        const char *p = q + nl;
        while (*p == ' ' || *p == '\t') ++p;
        if (*p != '=' && *p != ':') continue;
        p = skip_space(p + 1);
        if (elem >= 0) {
            if (*p != '[' && *p != '(') continue;
            p = skip_space(p + 1);
            for (int i = 0; i < elem; ++i) {
                char skip[64];
                p = skip_space(read_token(p, skip, sizeof skip));
                if (*p != ',') break;
                p = skip_space(p + 1);
            }
        }
        if (k-- == 0) return p;
    }
    return NULL;
}

int pl_scene_text_token(const pl_scene_text_t *t, int line, const char *name, int elem, char *lit, size_t nlit)
{
    const char *p = value_at(t, line, name, elem, 0);
    if (!p) return -1;
    size_t k = 0;
    while ((isalnum((unsigned char)*p) || strchr("+-.", *p)) && *p && k + 1 < nlit) lit[k++] = *p++;
    lit[k] = '\0';
    return k ? 0 : -1;
}

int pl_scene_text_integer(const pl_scene_text_t *t, int line, const char *name, int elem, long long libval,
                          long long *out, char *lit, size_t nlit)
{
    const char *p;
    for (int k = 0; (p = value_at(t, line, name, elem, k)); ++k) {
        read_token(p, lit, nlit);
        long long v = 0;
        int rc = parse_literal(lit, &v);
        if (rc == 1) return 1;
        if (rc == 0 && (v == libval || (long long)(int)v == libval)) {
            *out = v;
            return 0;
        }
    }
    return -1;
}
