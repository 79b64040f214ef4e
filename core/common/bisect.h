#pragma once
// The root of f between a and b, where f changes sign, by bisection: `iterations` halvings of
// the bracket (60 reach the double precision of a bracket of order 1).
namespace cutcell {

template <class F> double bisect(F f, double a, double b, int iterations = 60) {
    double fa = f(a);
    for (int i = 0; i < iterations; ++i) {
        const double m = 0.5 * (a + b), fm = f(m);
        if ((fm < 0) == (fa < 0)) {
            a = m;
            fa = fm;
        } else {
            b = m;
        }
    }
    return 0.5 * (a + b);
}

} // namespace cutcell
