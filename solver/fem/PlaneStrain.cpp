#include "fem/PlaneStrain.hpp"

namespace mcdda {

TriangleShape triangle_shape(const Point2& a, const Point2& b, const Point2& c) {
    TriangleShape s;
    const double twice_area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    s.area = 0.5 * twice_area;
    // Shape function gradients: ∂Ni/∂x = (yj − yk)/2A, ∂Ni/∂y = (xk − xj)/2A.
    const double bx[3] = {b.y - c.y, c.y - a.y, a.y - b.y};
    const double by[3] = {c.x - b.x, a.x - c.x, b.x - a.x};
    s.B.setZero();
    for (int i = 0; i < 3; ++i) {
        s.B(0, 2 * i) = bx[i] / twice_area;
        s.B(1, 2 * i + 1) = by[i] / twice_area;
        s.B(2, 2 * i) = by[i] / twice_area;
        s.B(2, 2 * i + 1) = bx[i] / twice_area;
    }
    return s;
}

}  // namespace mcdda
