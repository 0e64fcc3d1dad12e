/* quadsect from C99: both API levels, with every returned object freed.
 * Built and run by capi/run_examples.sh against libquadsect.a and
 * libquadsect.so; its output is compared with expected/example.txt. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "quadsect.h"

/* Prints an error and frees it. */
static void report(const char *what, int code, qs_error *err) {
    printf("%s: code %d, kind %s: %s\n", what, code, qs_error_kind(err), qs_error_message(err));
    qs_error_free(err);
}

/* Prints an interval of doubles rounded outward around an exact value. */
static void print_interval(const char *name, qs_interval iv) {
    if (!iv.known)
        printf("  %s unknown\n", name);
    else if (iv.exact)
        printf("  %s = %.17g exactly\n", name, iv.lo);
    else
        printf("  %s in [%.17g, %.17g] (neighbouring doubles: %s)\n", name, iv.lo, iv.hi,
               nextafter(iv.lo, INFINITY) == iv.hi ? "yes" : "no");
}

static const char *verdict_name(qs_verdict v) {
    switch (v) {
    case QS_VERDICT_INTERSECTING: return "intersecting";
    case QS_VERDICT_TOUCHING: return "touching";
    case QS_VERDICT_SEPARATED: return "separated";
    default: return "undecided";
    }
}

int main(void) {
    int failures = 0;
    qs_error *err = NULL;
    char *json = NULL;
    int code;

    printf("header %s, library %s, same: %s\n", QS_VERSION, qs_version(),
           strcmp(QS_VERSION, qs_version()) == 0 ? "yes" : "no");

    /* 1. JSON level: the paper's Example 1 (separated, min 7/9, max 187/9) */
    code = qs_tangent_json("x^2 + y^2 + z^2 - 25", "(x-9)^2/9 + y^2/4 + z^2/16 - 1", &json, &err);
    if (code == QS_OK) {
        printf("tangent json: separated %s, min 7/9 %s\n",
               strstr(json, "\"verdict\":\"separated\"") ? "yes" : "no",
               strstr(json, "\"min\":{\"poly\":\"9*u - 7\"") ? "yes" : "no");
        qs_string_free(json);
    } else {
        report("tangent json", code, err);
        failures++;
    }

    /* a malformed surface: code 2 and a message with the column */
    code = qs_tangent_json("x^2 + y^2 + z^2 - 1", "x^2 + * y", &json, &err);
    if (code == QS_ERR_INPUT && json == NULL)
        report("bad surface", code, err);
    else
        failures++;

    /* 2. one line of the batch protocol */
    char *line = NULL;
    code = qs_batch_line("{\"id\":1,\"op\":\"resultant\",\"f\":\"x^2+y^2-1\",\"g\":\"x-y\",\"var\":\"x\"}",
                         &line);
    if (code == QS_OK) {
        printf("batch: %s\n", line);
        qs_string_free(line);
    } else {
        failures++;
    }

    /* 3. typed level: two perpendicular unit cylinders meet in two ellipses */
    qs_natural_f64 a = {QS_CYLINDER, {0, 0, 0}, {1, 0, 0}, 1.0};
    qs_natural_f64 b = {QS_CYLINDER, {0, 0, 0}, {0, 1, 0}, 1.0};
    qs_natural_result nr;
    code = qs_natural_classify_f64(&a, &b, &nr, &err);
    if (code == QS_OK)
        printf("cylinders: class conics %s, %u conics, %u lines, %u points, thm8 %d\n",
               nr.cls == QS_CLASS_CONICS ? "yes" : "no", nr.conics, nr.lines, nr.points,
               (int)nr.thm8);
    else {
        report("cylinders", code, err);
        failures++;
    }

    /* 4. typed tangent: Example 1 again, S scaled by 144 (x², y², z², xy, xz, yz, x, y, z, 1) */
    qs_ellipsoid_f64 e = {{0, 0, 0}, {5, 5, 5}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    double s[10] = {16, 36, 9, 0, 0, 0, -288, 0, 0, 1152};
    qs_tangent_result tr;
    code = qs_tangent_quadric_f64(&e, s, &tr, &err);
    if (code == QS_OK) {
        printf("example 1 in doubles: %s, side %d\n", verdict_name(tr.verdict), (int)tr.side);
        print_interval("min", tr.minimum);
        print_interval("max", tr.maximum);
    } else {
        report("example 1", code, err);
        failures++;
    }

    /* the plane x + y on the unit sphere: extremes -sqrt(2) and sqrt(2) */
    qs_ellipsoid_f64 unit = {{0, 0, 0}, {1, 1, 1}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    double plane[10] = {0, 0, 0, 0, 0, 0, 1, 1, 0, 0};
    code = qs_tangent_quadric_f64(&unit, plane, &tr, &err);
    if (code == QS_OK) {
        printf("x + y on the unit sphere: %s\n", verdict_name(tr.verdict));
        print_interval("min", tr.minimum);
        print_interval("max", tr.maximum);
        printf("  sqrt(2) inside: %s\n",
               tr.maximum.lo <= sqrt(2.0) && sqrt(2.0) <= tr.maximum.hi ? "yes" : "no");
    } else {
        report("plane", code, err);
        failures++;
    }

    /* a NaN coordinate is bad input, never a crash */
    a.point[1] = NAN;
    code = qs_natural_classify_f64(&a, &b, &nr, &err);
    if (code == QS_ERR_INPUT)
        report("NaN", code, err);
    else
        failures++;

    /* 5. options: a time limit for the next calls */
    qs_options *opts = qs_options_new();
    code = qs_options_set_time_limit(opts, 2.5, &err);
    if (code == QS_OK) {
        code = qs_natural_json_opts("sphere center=0,0,0 radius2=1", "sphere center=1,0,0 radius2=1",
                                    opts, &json, &err);
        if (code == QS_OK) {
            printf("spheres with a 2.5 s limit: circle %s\n",
                   strstr(json, "\"class\":\"conics\"") ? "yes" : "no");
            qs_string_free(json);
        } else {
            report("spheres", code, err);
            failures++;
        }
    } else {
        report("time limit", code, err);
        failures++;
    }

    /* 6. a budget that runs out: code 3, an error saying which limit, and
     * the undecided answer; both are ours to free */
    qs_options_set_time_limit(opts, 0.0, NULL);
    code = qs_tangent_json_opts("x^2 + y^2 + z^2 - 1", "x - 3", opts, &json, &err);
    if (code == QS_ERR_BUDGET && json != NULL) {
        printf("zero time limit: code %d, kind %s, undecided %s\n", code, qs_error_kind(err),
               strstr(json, "\"verdict\":\"undecided\"") ? "yes" : "no");
        qs_error_free(err);
    } else {
        report("zero time limit", code, err);
        failures++;
    }
    qs_string_free(json);
    code = qs_tangent_quadric_f64_opts(&unit, plane, opts, &tr, &err);
    if (code == QS_ERR_BUDGET)
        printf("  typed: %s, reason budget %s\n", verdict_name(tr.verdict),
               tr.reason == QS_UNDECIDED_BUDGET ? "yes" : "no");
    else
        failures++;
    qs_error_free(err);
    qs_options_free(opts);

    printf("%s\n", failures == 0 ? "all calls behaved" : "SOME CALLS MISBEHAVED");
    return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
