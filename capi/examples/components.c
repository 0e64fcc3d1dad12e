/* The components of two natural quadrics as doubles with proven error
 * bounds (qs_natural_components_f64): conics, lines, isolated points and
 * space curves, each number a qs_ball {value, bound} with
 * |exact - value| <= bound.  One result per pair, freed with
 * qs_natural_components_free.  Built and run by capi/run_examples.sh
 * against libquadsect.a and libquadsect.so; its output is compared with
 * expected/components.txt. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "quadsect.h"

static const char *class_name(qs_class c) {
    switch (c) {
    case QS_CLASS_SAME_SURFACE: return "same surface";
    case QS_CLASS_CONICS: return "conics";
    case QS_CLASS_CONIC_AND_LINE: return "conic and line";
    case QS_CLASS_LINES: return "lines";
    case QS_CLASS_POINTS: return "points";
    case QS_CLASS_EMPTY: return "empty";
    case QS_CLASS_CURVE: return "curve";
    default: return "undecided";
    }
}

static const char *conic_name(qs_conic_kind k) {
    switch (k) {
    case QS_CONIC_CIRCLE: return "circle";
    case QS_CONIC_ELLIPSE: return "ellipse";
    case QS_CONIC_HYPERBOLA: return "hyperbola";
    default: return "parabola";
    }
}

static const char *point_name(qs_point_kind k) {
    switch (k) {
    case QS_POINT_TANGENCY: return "tangency";
    case QS_POINT_VERTEX: return "vertex";
    default: return "acnode";
    }
}

static const char *singular_name(qs_singular_kind k) {
    switch (k) {
    case QS_SINGULAR_ACNODE: return "acnode";
    case QS_SINGULAR_CROSSING: return "crossing";
    case QS_SINGULAR_CUSP: return "cusp";
    default: return "tacnode";
    }
}

/* A number: the value, and its bound when it is not exact. */
static void ball(qs_ball b) {
    if (b.bound == 0)
        printf("%.17g", b.value);
    else
        printf("%.17g~%.1e", b.value, b.bound);
}

static void point(const qs_ball p[3]) {
    printf("(");
    for (int i = 0; i < 3; i++) {
        if (i) printf(", ");
        ball(p[i]);
    }
    printf(")");
}

/* The widest bound relative to the value in a triple, to show that the
 * doubles are within a few units in the last place. */
static double worst(const qs_ball p[3]) {
    double w = 0;
    for (int i = 0; i < 3; i++) {
        double r = p[i].bound / fmax(fabs(p[i].value), 1.0);
        if (r > w) w = r;
    }
    return w;
}

static void print_component(const qs_component *c) {
    switch (c->tag) {
    case QS_COMPONENT_CONIC: {
        const qs_conic *k = &c->data.conic;
        printf("  %s%s in the plane ", k->is_double ? "double " : "", conic_name(k->kind));
        point(k->normal);
        printf(" . P = ");
        ball(k->offset);
        printf("\n    %s ", k->is_vertex ? "vertex" : "centre");
        point(k->center);
        for (unsigned i = 0; i < k->n_semi_axes2; i++) {
            printf("\n    semi-axis^2 ");
            ball(k->semi_axes2[i]);
            printf(" along ");
            point(k->axis_dirs[i]);
        }
        if (k->n_semi_axes2 == 0) { /* a parabola: its axis and focal length^2 */
            printf("\n    axis ");
            point(k->axis_dirs[0]);
            printf(", focal length^2 ");
            ball(k->focal2);
        }
        printf("\n");
        break;
    }
    case QS_COMPONENT_LINE: {
        const qs_line *l = &c->data.line;
        printf("  %sline through ", l->is_double ? "double " : "");
        point(l->point);
        printf("\n    direction ");
        point(l->direction);
        printf("\n    relative bound <= 1e-14: %s\n",
               worst(l->point) <= 1e-14 && worst(l->direction) <= 1e-14 ? "yes" : "no");
        break;
    }
    case QS_COMPONENT_POINT: {
        const qs_point *p = &c->data.point;
        printf("  %s point ", point_name(p->kind));
        point(p->point);
        printf("\n");
        break;
    }
    case QS_COMPONENT_CURVE: {
        /* the arrays belong to the result: no free of their own */
        const qs_curve *k = &c->data.curve;
        printf("  curve of degree %u, %zu singular point(s), %zu branch(es)\n", k->degree,
               k->n_singular, k->n_branches);
        for (size_t i = 0; i < k->n_singular; i++) {
            printf("    %s at ", singular_name(k->singular[i].kind));
            point(k->singular[i].point);
            printf("\n");
        }
        /* branch points come from double balls: print them to 1e-9 */
        for (size_t i = 0; i < k->n_branches; i++) {
            const qs_curve_branch *b = &k->branches[i];
            printf("    %s branch through (%.9f, %.9f, %.9f), bound <= 1e-9: %s\n",
                   b->bounded ? "closed" : "unbounded", b->point[0].value, b->point[1].value,
                   b->point[2].value, worst(b->point) <= 1e-9 ? "yes" : "no");
        }
        break;
    }
    default: printf("  a component of unknown type %d\n", (int)c->tag);
    }
}

/* Classifies a pair, prints its components, frees the result; 1 on failure. */
static int show(const char *what, qs_natural_f64 a, qs_natural_f64 b) {
    qs_natural_components *r = NULL;
    qs_error *err = NULL;
    int code = qs_natural_components_f64(&a, &b, NULL, &r, &err);
    if (code != QS_OK) {
        printf("%s: code %d, %s: %s\n", what, code, qs_error_kind(err), qs_error_message(err));
        qs_error_free(err);
        qs_natural_components_free(r); /* NULL, or the undecided result of code 3 */
        return 1;
    }
    printf("%s: %s, %u conic(s), %u line(s), %u point(s), %zu component(s)\n", what,
           class_name(r->result.cls), r->result.conics, r->result.lines, r->result.points, r->count);
    for (size_t i = 0; i < r->count; i++) print_component(&r->components[i]);
    qs_natural_components_free(r);
    return 0;
}

int main(void) {
    int failures = 0;
    qs_natural_f64 cyl_x = {QS_CYLINDER, {0, 0, 0}, {1, 0, 0}, 1.0};
    qs_natural_f64 cyl_y = {QS_CYLINDER, {0, 0, 0}, {0, 1, 0}, 1.0};
    failures += show("perpendicular unit cylinders", cyl_x, cyl_y);

    qs_natural_f64 s1 = {QS_SPHERE, {0, 0, 0}, {0, 0, 0}, 2.0};
    qs_natural_f64 s2 = {QS_SPHERE, {0.5, 0.25, 0}, {0, 0, 0}, 3.0};
    failures += show("two spheres", s1, s2);

    qs_natural_f64 cone_x = {QS_CONE, {0, 0, 0}, {1, 0, 0}, 1.0};
    qs_natural_f64 cone_y = {QS_CONE, {0, 0, 0}, {0, 1, 0}, 3.0};
    failures += show("cones with a common vertex", cone_x, cone_y);

    qs_natural_f64 cone_z = {QS_CONE, {0, 0, 0}, {0, 0, 1}, 1.0};
    qs_natural_f64 s3 = {QS_SPHERE, {0, 0, 2}, {0, 0, 0}, 4.0};
    failures += show("sphere through a cone's vertex", s3, cone_z);

    qs_natural_f64 cone_p = {QS_CONE, {2, 2, 0}, {0, 1, 0}, 1.0};
    failures += show("cone and cone", cone_x, cone_p);

    qs_natural_f64 cone_c = {QS_CONE, {0, 1, 0}, {1, 1, 0}, 3.0};
    failures += show("cylinder and cone", cyl_x, cone_c);

    /* bad input: code 2, no result to free */
    qs_natural_f64 bad = cyl_x;
    bad.param = NAN;
    qs_natural_components *r = NULL;
    qs_error *err = NULL;
    int code = qs_natural_components_f64(&bad, &cyl_y, NULL, &r, &err);
    printf("NaN radius^2: code %d, result %s, %s\n", code, r == NULL ? "NULL" : "set",
           qs_error_message(err));
    qs_error_free(err);
    if (code != QS_ERR_INPUT || r != NULL) failures++;

    printf("%s\n", failures == 0 ? "all calls behaved" : "SOME CALLS MISBEHAVED");
    return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
