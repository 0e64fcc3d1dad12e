// quadsect from C++11: RAII owners for the library's objects, errors as
// exceptions, and calls from several threads at once (the library has no
// global state).  Built and run by capi/run_examples.sh against
// libquadsect.a and libquadsect.so; its output is compared with
// expected/example_cpp.txt.
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "quadsect.h"

namespace {

// Owners that call the library's free functions.
struct ErrorFree {
    void operator()(qs_error *e) const { qs_error_free(e); }
};
struct StringFree {
    void operator()(char *s) const { qs_string_free(s); }
};
struct OptionsFree {
    void operator()(qs_options *o) const { qs_options_free(o); }
};
using Error = std::unique_ptr<qs_error, ErrorFree>;
using String = std::unique_ptr<char, StringFree>;
using Options = std::unique_ptr<qs_options, OptionsFree>;

// A failed call as an exception carrying the code, kind and message.
struct QsError : std::runtime_error {
    int code;
    std::string kind;
    QsError(int c, const qs_error *e)
        : std::runtime_error(qs_error_message(e)), code(c), kind(qs_error_kind(e)) {}
};

void check(int code, qs_error *raw) {
    Error e(raw);  // freed on every path
    if (code != QS_OK) throw QsError(code, e.get());
}

std::string natural_json(const std::string &a, const std::string &b, const qs_options *o) {
    char *out = nullptr;
    qs_error *err = nullptr;
    int code = qs_natural_json_opts(a.c_str(), b.c_str(), o, &out, &err);
    String owned(out);
    check(code, err);
    return std::string(owned.get());
}

qs_natural_result classify(const qs_natural_f64 &a, const qs_natural_f64 &b) {
    qs_natural_result r;
    qs_error *err = nullptr;
    check(qs_natural_classify_f64(&a, &b, &r, &err), err);
    return r;
}

qs_tangent_result tangent(const qs_ellipsoid_f64 &e, const double (&s)[10]) {
    qs_tangent_result r;
    qs_error *err = nullptr;
    check(qs_tangent_quadric_f64(&e, s, &r, &err), err);
    return r;
}

const char *class_name(qs_class c) {
    switch (c) {
    case QS_CLASS_SAME_SURFACE: return "same surface";
    case QS_CLASS_CONICS: return "conics";
    case QS_CLASS_CONIC_AND_LINE: return "conic and line";
    case QS_CLASS_LINES: return "lines";
    case QS_CLASS_POINTS: return "points";
    case QS_CLASS_EMPTY: return "empty";
    case QS_CLASS_CURVE: return "curve";
    default: return "?";
    }
}

}  // namespace

int main() {
    std::printf("quadsect %s (header %s)\n", qs_version(), QS_VERSION);

    // Four threads at once, each classifying the unit cylinder about the
    // z axis against a unit sphere centred at distance d from the axis:
    // d = 0 touches along a circle, d = 0.5 is a quartic curve, d = 2
    // touches in one point, d = 3 misses.
    const double d[4] = {0, 0.5, 2, 3};
    std::vector<qs_natural_result> results(4);
    std::vector<std::thread> threads;
    for (int i = 0; i < 4; ++i) {
        threads.emplace_back([i, &d, &results] {
            qs_natural_f64 cyl = {QS_CYLINDER, {0, 0, 0}, {0, 0, 1}, 1.0};
            qs_natural_f64 sph = {QS_SPHERE, {d[i], 0, 0}, {0, 0, 0}, 1.0};
            for (int k = 0; k < 10; ++k) results[i] = classify(cyl, sph);
        });
    }
    for (auto &t : threads) t.join();
    for (int i = 0; i < 4; ++i)
        std::printf("sphere at d = %.1f: %s, %u conics, %u lines, %u points\n", d[i],
                    class_name(results[i].cls), results[i].conics, results[i].lines,
                    results[i].points);

    // A rotated ellipsoid whose rotation is stored in doubles (orthogonal
    // only up to rounding) against the plane z = 10: taken exactly.
    const double c = std::sqrt(3.0) / 2, s = 0.5;
    qs_ellipsoid_f64 e = {{1, 2, 3}, {3, 2, 1}, {{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
    const double plane[10] = {0, 0, 0, 0, 0, 0, 0, 0, 1, -10};
    qs_tangent_result t = tangent(e, plane);
    std::printf("rotated ellipsoid vs z = 10: separated %s, side %d, S from %g to %g (exact %d %d)\n",
                t.verdict == QS_VERDICT_SEPARATED ? "yes" : "no", (int)t.side, t.minimum.lo,
                t.maximum.hi, (int)t.minimum.exact, (int)t.maximum.exact);

    // Options shared by several calls.
    Options opts(qs_options_new());
    qs_error *err = nullptr;
    check(qs_options_set_time_limit(opts.get(), 1.0, &err), err);
    std::string j = natural_json("cone vertex=0,0,0 axis=1,0,0 tan2=1",
                                 "cone vertex=0,0,0 axis=0,1,0 tan2=3", opts.get());
    std::printf("two cones with a common vertex: lines %s\n",
                j.find("\"class\":\"lines\"") != std::string::npos ? "yes" : "no");

    // Errors become exceptions; nothing leaks.
    try {
        natural_json("cone vertex=0,0,0 axis=0,0,0 tan2=1", "sphere center=0,0,0 radius2=1",
                     nullptr);
        std::printf("no exception?\n");
        return 1;
    } catch (const QsError &x) {
        std::printf("caught: code %d, kind %s: %s\n", x.code, x.kind.c_str(), x.what());
    }
    std::printf("done\n");
    return 0;
}
