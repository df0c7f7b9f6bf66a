#pragma once
/// \file TriangleElement.hpp
/// The two block-interior elements, as one description that assembly, stress update, mass, loads
/// and output share: nodes per element, shape functions, integration points and their weights.
///
///   T3  three-node triangle (constant strain), 1 point at the centroid — exact for its constant
///       B; locks under isochoric plastic flow (ψ = 0) on unstructured meshes.
///   T6  six-node triangle with straight edges (linear strain), nodes c0 c1 c2 m01 m12 m20,
///       3 points at area coordinates (2/3, 1/6, 1/6) and permutations, weight A/3 each. The rule
///       is of degree 2, so the stiffness ∫BᵀDB (B linear) is exact; 3 points per element give
///       about 4/3 displacement degrees of freedom per incompressibility constraint in plane
///       strain, which is why T6 does not lock where T3 does (Sloan & Randolph 1982; the paper's
///       remark on higher-order elements).
///
/// Voigt order (xx, yy, xy) with engineering shear strain γxy, as in PlaneStrain.hpp.

#include "model/Model.hpp"

#include <Eigen/Dense>

#include <array>

namespace mcdda {

template <int Nodes>
struct TriangleElement {
    static_assert(Nodes == 3 || Nodes == 6, "three- or six-node triangles");
    static constexpr int nodes = Nodes;
    static constexpr int dofs = 2 * Nodes;
    static constexpr int points = Nodes == 3 ? 1 : 3;
    using Strain = Eigen::Matrix<double, 3, dofs>;   ///< ε = B·(u1, v1, u2, v2, …)
    using Stiffness = Eigen::Matrix<double, dofs, dofs>;
    using Forces = Eigen::Matrix<double, dofs, 1>;

    /// Area coordinates of integration point q.
    static std::array<double, 3> point(int q) {
        if (Nodes == 3) return {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
        std::array<double, 3> l{1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0};
        l[q] = 2.0 / 3.0;
        return l;
    }

    /// Geometry of one element on given coordinates: area, B at each point, weight (area share).
    struct Geometry {
        double area = 0.0;
        std::array<Strain, points> B;
        double weight(int) const { return area / points; }
    };

    /// Shape functions at area coordinates l.
    static std::array<double, Nodes> shape(const std::array<double, 3>& l) {
        std::array<double, Nodes> n{};
        if constexpr (Nodes == 3) {
            n = {l[0], l[1], l[2]};
        } else {
            for (int i = 0; i < 3; ++i) n[i] = l[i] * (2.0 * l[i] - 1.0);
            for (int k = 0; k < 3; ++k) n[3 + k] = 4.0 * l[k] * l[(k + 1) % 3];
        }
        return n;
    }

    /// `x` holds the corner coordinates (the midside nodes of a straight-sided T6 sit at the
    /// middles of the edges, so the corners define the geometry).
    static Geometry geometry(const Point2& a, const Point2& b, const Point2& c) {
        Geometry g;
        const double twice_area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        g.area = 0.5 * twice_area;
        // ∂Li/∂x = (yj − yk)/2A, ∂Li/∂y = (xk − xj)/2A.
        const double lx[3] = {(b.y - c.y) / twice_area, (c.y - a.y) / twice_area, (a.y - b.y) / twice_area};
        const double ly[3] = {(c.x - b.x) / twice_area, (a.x - c.x) / twice_area, (b.x - a.x) / twice_area};
        for (int q = 0; q < points; ++q) {
            const std::array<double, 3> l = point(q);
            double nx[Nodes], ny[Nodes];
            if constexpr (Nodes == 3) {
                for (int i = 0; i < 3; ++i) nx[i] = lx[i], ny[i] = ly[i];
            } else {
                for (int i = 0; i < 3; ++i) {
                    nx[i] = (4.0 * l[i] - 1.0) * lx[i];
                    ny[i] = (4.0 * l[i] - 1.0) * ly[i];
                }
                for (int k = 0; k < 3; ++k) {
                    const int j = (k + 1) % 3;
                    nx[3 + k] = 4.0 * (l[k] * lx[j] + l[j] * lx[k]);
                    ny[3 + k] = 4.0 * (l[k] * ly[j] + l[j] * ly[k]);
                }
            }
            Strain& B = g.B[q];
            B.setZero();
            for (int i = 0; i < Nodes; ++i) {
                B(0, 2 * i) = nx[i];
                B(1, 2 * i + 1) = ny[i];
                B(2, 2 * i) = ny[i];
                B(2, 2 * i + 1) = nx[i];
            }
        }
        return g;
    }

    /// Consistent mass ∫NiNj dA per unit density and area (one direction).
    static double mass(int i, int j) {
        if constexpr (Nodes == 3) {
            return (i == j ? 2.0 : 1.0) / 12.0;
        } else {
            // Straight-sided T6, order c0 c1 c2 m01 m12 m20 (e.g. Zienkiewicz & Taylor).
            static constexpr double m[6][6] = {{6, -1, -1, 0, -4, 0},   {-1, 6, -1, 0, 0, -4},
                                               {-1, -1, 6, -4, 0, 0},   {0, 0, -4, 32, 16, 16},
                                               {-4, 0, 0, 16, 32, 16},  {0, -4, 0, 16, 16, 32}};
            return m[i][j] / 180.0;
        }
    }

    /// ∫Ni dA per unit area: a uniform body force's share of node i (corners of T6 get none).
    static double body_share(int i) {
        if constexpr (Nodes == 3) return 1.0 / 3.0;
        else return i < 3 ? 0.0 : 1.0 / 3.0;
    }
};

using Triangle3 = TriangleElement<3>;
using Triangle6 = TriangleElement<6>;

}  // namespace mcdda
