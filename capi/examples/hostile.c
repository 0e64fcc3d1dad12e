/* Hostile input through the C API: every case must return code 2 (bad
 * input) with a kind and a non-empty message, and never crash.  Run by
 * capi/run_examples.sh (also under valgrind); prints one line per failure
 * and a closing "hostile: N passed, M failed". */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quadsect.h"

static int passed = 0, failed = 0;
static int verbose = 0; /* HOSTILE_VERBOSE=1 prints every message */

/* Checks a failed call: code 2, an error with a kind and a message, no
 * output; frees the error. */
static void expect_input_error(const char *what, int code, qs_error *err, const void *out) {
    const char *msg = qs_error_message(err);
    const char *kind = qs_error_kind(err);
    if (code == QS_ERR_INPUT && err != NULL && msg != NULL && msg[0] != '\0' && kind != NULL &&
        qs_error_code(err) == QS_ERR_INPUT && out == NULL) {
        passed++;
        if (verbose) printf("ok %s: %s: %.100s\n", what, kind, msg);
    } else {
        failed++;
        printf("FAILED %s: code %d, kind %s, message %s\n", what, code, kind ? kind : "(null)",
               msg ? msg : "(null)");
    }
    qs_error_free(err);
}

static void check(const char *what, int ok) {
    if (ok) {
        passed++;
    } else {
        failed++;
        printf("FAILED %s\n", what);
    }
}

static void tangent_json(const char *what, const char *e, const char *s) {
    char *out = NULL;
    qs_error *err = NULL;
    int code = qs_tangent_json(e, s, &out, &err);
    expect_input_error(what, code, err, out);
    qs_string_free(out);
}

static void natural_json(const char *what, const char *a, const char *b) {
    char *out = NULL;
    qs_error *err = NULL;
    int code = qs_natural_json(a, b, &out, &err);
    expect_input_error(what, code, err, out);
    qs_string_free(out);
}

static void natural_f64(const char *what, const qs_natural_f64 *a, const qs_natural_f64 *b) {
    qs_natural_result r;
    qs_error *err = NULL;
    int code = qs_natural_classify_f64(a, b, &r, &err);
    expect_input_error(what, code, err, NULL);
    check(what, r.conics == 0 && r.lines == 0 && r.points == 0);
}

static void natural_components(const char *what, const qs_natural_f64 *a, const qs_natural_f64 *b) {
    qs_natural_components *out = (qs_natural_components *)&out; /* garbage to be cleared */
    qs_error *err = NULL;
    int code = qs_natural_components_f64(a, b, NULL, &out, &err);
    expect_input_error(what, code, err, out);
    qs_natural_components_free(out); /* NULL: does nothing */
}

static void tangent_f64(const char *what, const qs_ellipsoid_f64 *e, const double *q) {
    qs_tangent_result r;
    qs_error *err = NULL;
    int code = qs_tangent_quadric_f64(e, q, &r, &err);
    expect_input_error(what, code, err, NULL);
    check(what, r.verdict == QS_VERDICT_UNDECIDED && !r.minimum.known && isnan(r.maximum.lo));
}

/* A string of `n` copies of `unit` (malloc'd). */
static char *repeat(const char *unit, size_t n) {
    size_t k = strlen(unit);
    char *s = malloc(k * n + 1);
    if (!s) exit(2);
    for (size_t i = 0; i < n; i++) memcpy(s + i * k, unit, k);
    s[k * n] = '\0';
    return s;
}

int main(void) {
    verbose = getenv("HOSTILE_VERBOSE") != NULL;
    const char *sphere = "x^2 + y^2 + z^2 - 1";

    /* malformed expressions */
    tangent_json("unbalanced bracket", sphere, "x^2 + )");
    tangent_json("empty surface", sphere, "");
    tangent_json("dangling power", sphere, "x^");
    tangent_json("division by zero", sphere, "x/0");
    tangent_json("negative power", sphere, "x^-1");
    tangent_json("unknown variable", sphere, "w + 1");
    tangent_json("hyperboloid", "x^2 + y^2 - z^2 - 1", "x");
    tangent_json("empty ellipsoid", "x^2 + y^2 + z^2 + 1", "x");
    tangent_json("zero surface", sphere, "0");
    tangent_json("huge number", sphere, "x - 1e999999999999");
    natural_json("bad natural syntax", "sphere centre=(0,0,0)", "sphere center=0,0,0 radius2=1");
    natural_json("negative radius", "sphere center=0,0,0 radius2=-1", "sphere center=0,0,0 radius2=1");
    natural_json("bad JSON object", "{\"kind\":\"cone\",\"vertex\":[1,2]}", "sphere center=0,0,0 radius2=1");

    /* huge expressions: too long, too high a degree, too deep (each refused
     * by the parser's limits before any work) */
    char *longest = repeat("x+", 1 << 20);
    tangent_json("2 MiB expression", sphere, longest);
    free(longest);
    tangent_json("degree 20000", sphere, "x^20000 + y");
    char *deep = repeat("(", 200000);
    tangent_json("200000 nested brackets", sphere, deep);
    free(deep);

    /* invalid UTF-8 */
    tangent_json("invalid UTF-8 surface", sphere, "x^2 \xff\xfe + 1");
    natural_json("invalid UTF-8 quadric", "sphere center=0,0,0 radius2=1", "\xc3\x28");

    /* NULL pointers */
    char *out = NULL;
    qs_error *err = NULL;
    tangent_json("NULL ellipsoid", NULL, "x");
    tangent_json("NULL surface", sphere, NULL);
    natural_json("NULL quadric", NULL, NULL);
    int code = qs_tangent_json(sphere, "x", NULL, &err);
    expect_input_error("NULL out_json", code, err, NULL);
    check("NULL err still returns the code", qs_tangent_json(sphere, "x^2 + ", &out, NULL) == QS_ERR_INPUT && out == NULL);
    check("NULL batch line", qs_batch_line(NULL, &out) == QS_ERR_INPUT && out == NULL);
    check("NULL batch out", qs_batch_line("{}", NULL) == QS_ERR_INPUT);
    check("NULL error accessors", qs_error_message(NULL) == NULL && qs_error_kind(NULL) == NULL &&
                                      qs_error_code(NULL) == QS_OK);
    qs_error_free(NULL);
    qs_string_free(NULL);
    qs_options_free(NULL);
    qs_options_cancel(NULL);

    /* batch lines are always answered, bad ones with an error line */
    code = qs_batch_line("not json \xff", &out);
    check("bad batch line answered", code == QS_OK && out && strstr(out, "\"ok\":false"));
    qs_string_free(out);
    code = qs_batch_line("{\"op\":\"explode\"}", &out);
    check("unknown op answered", code == QS_OK && out && strstr(out, "\"unknown-op\""));
    qs_string_free(out);

    /* NaN, infinite and invalid doubles */
    qs_natural_f64 good = {QS_SPHERE, {0, 0, 0}, {0, 0, 0}, 1.0};
    qs_natural_f64 bad = good;
    bad.point[2] = NAN;
    natural_f64("NaN centre", &bad, &good);
    bad = good;
    bad.param = INFINITY;
    natural_f64("infinite radius2", &good, &bad);
    bad = good;
    bad.param = 0.0;
    natural_f64("zero radius2", &bad, &good);
    bad.kind = 42;
    bad.param = 1.0;
    natural_f64("unknown kind", &bad, &good);
    qs_natural_f64 cyl = {QS_CYLINDER, {0, 0, 0}, {0, 0, 0}, 1.0};
    natural_f64("zero axis", &cyl, &good);
    cyl.axis[0] = -NAN;
    natural_f64("NaN axis", &cyl, &good);
    natural_f64("NULL a", NULL, &good);
    qs_natural_result nr;
    code = qs_natural_classify_f64(&good, &good, NULL, &err);
    expect_input_error("NULL natural out", code, err, NULL);
    (void)nr;

    /* the typed components: the same refusals, *out NULL (even when it held
     * garbage), nothing to free */
    bad = good;
    bad.point[0] = NAN;
    natural_components("components: NaN centre", &bad, &good);
    bad = good;
    bad.param = -INFINITY;
    natural_components("components: infinite radius2", &good, &bad);
    bad = good;
    bad.param = -1.0;
    natural_components("components: negative radius2", &bad, &good);
    bad.kind = -7;
    bad.param = 1.0;
    natural_components("components: unknown kind", &bad, &good);
    cyl.axis[0] = 0.0;
    natural_components("components: zero axis", &good, &cyl);
    cyl.axis[1] = INFINITY;
    natural_components("components: infinite axis", &cyl, &good);
    natural_components("components: NULL a", NULL, &good);
    natural_components("components: NULL b", &good, NULL);
    code = qs_natural_components_f64(&good, &good, NULL, NULL, &err);
    expect_input_error("components: NULL out", code, err, NULL);
    check("components: NULL err still returns the code",
          qs_natural_components_f64(NULL, NULL, NULL, NULL, NULL) == QS_ERR_INPUT);
    qs_natural_components_free(NULL);
    /* extreme but valid doubles: an answer, never a crash, and no infinite
     * direction (directions are scaled into the range of doubles) */
    qs_natural_f64 tiny = {QS_CYLINDER, {0, 0, 0}, {0, 1e-300, 3e-300}, 1.0};
    qs_natural_f64 tiny2 = {QS_CYLINDER, {1, 0, 0}, {0, 1e-300, 3e-300}, 1.0};
    qs_natural_components *nc = NULL;
    code = qs_natural_components_f64(&tiny, &tiny2, NULL, &nc, NULL);
    int finite = code == QS_OK && nc != NULL && nc->count == 2;
    for (size_t i = 0; finite && i < nc->count; i++)
        for (int k = 0; k < 3; k++)
            finite = finite && nc->components[i].tag == QS_COMPONENT_LINE &&
                     isfinite(nc->components[i].data.line.direction[k].value);
    check("components: axes of 1e-300 give two finite lines", finite);
    qs_natural_components_free(nc);

    qs_ellipsoid_f64 e = {{0, 0, 0}, {1, 1, 1}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    double q[10] = {0, 0, 0, 0, 0, 0, 1, 0, 0, 0};
    qs_ellipsoid_f64 be = e;
    be.center[0] = NAN;
    tangent_f64("NaN ellipsoid centre", &be, q);
    be = e;
    be.semi_axes[1] = -1;
    tangent_f64("negative semi-axis", &be, q);
    be = e;
    be.rotation[2][2] = 0;
    tangent_f64("singular rotation", &be, q);
    be = e;
    be.rotation[0][1] = INFINITY;
    tangent_f64("infinite rotation entry", &be, q);
    double bq[10] = {0, 0, 0, 0, 0, 0, 1, 0, 0, NAN};
    tangent_f64("NaN coefficient", &e, bq);
    double zq[10] = {0};
    tangent_f64("zero quadric", &e, zq);
    tangent_f64("NULL quadric", &e, NULL);
    tangent_f64("NULL ellipsoid", NULL, q);

    /* options */
    qs_options *o = qs_options_new();
    check("options made", o != NULL);
    code = qs_options_set_time_limit(o, NAN, &err);
    expect_input_error("NaN time limit", code, err, NULL);
    code = qs_options_set_time_limit(o, -1.0, &err);
    expect_input_error("negative time limit", code, err, NULL);
    code = qs_options_set_time_limit(NULL, 1.0, &err);
    expect_input_error("NULL options", code, err, NULL);
    qs_options_free(o);

    printf("hostile: %d passed, %d failed\n", passed, failed);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
