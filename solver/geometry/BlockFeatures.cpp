#include "geometry/BlockFeatures.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace mcdda {

namespace {

struct Edge {
    Point2 a, b;
    int ring = 0, from = 0, to = 0;  ///< vertex indices within the ring
};

std::string metres(double value) {
    std::ostringstream out;
    out.precision(3);
    out << value << " m";
    return out.str();
}

}  // namespace

std::optional<SmallFeature> find_small_feature(const Block& block, double tolerance) {
    std::vector<const Ring*> rings{&block.outer};
    for (const Ring& h : block.holes) rings.push_back(&h);
    std::vector<Edge> edges;
    double perimeter = 0.0;
    for (std::size_t r = 0; r < rings.size(); ++r) {
        const Ring& ring = *rings[r];
        const int n = static_cast<int>(ring.size());
        for (int k = 0; k < n; ++k) {
            const Edge e{ring[k], ring[(k + 1) % n], static_cast<int>(r), k, (k + 1) % n};
            const double length = std::hypot(e.b.x - e.a.x, e.b.y - e.a.y);
            if (!(length >= tolerance))
                return SmallFeature{length, e.a, "an edge " + metres(length) + " long"};
            perimeter += length;
            edges.push_back(e);
        }
    }
    // A crack is a ring of its own (from, to), so that its ends are checked against everything
    // else and everything against it; ends it shares with the block's rings or other cracks are
    // the same point, topology again.
    std::vector<Ring> crack_rings;
    for (const Block::Crack& c : block.cracks) crack_rings.push_back({c.from, c.to});
    for (const Ring& c : crack_rings) {
        const double length = std::hypot(c[1].x - c[0].x, c[1].y - c[0].y);
        if (!(length >= tolerance)) return SmallFeature{length, c[0], "a crack " + metres(length) + " long"};
        perimeter += length;
        edges.push_back({c[0], c[1], static_cast<int>(rings.size()), 0, 1});
        rings.push_back(&c);
    }
    if (edges.empty()) return std::nullopt;
    // Edges binned in square cells about as large as an average edge (never below the
    // tolerance): a vertex is compared with the edges of its own and the neighbouring cells.
    const double cell = std::max(perimeter / static_cast<double>(edges.size()), 2.0 * tolerance);
    Point2 low = edges.front().a;
    for (const Edge& e : edges) low = {std::min({low.x, e.a.x, e.b.x}), std::min({low.y, e.a.y, e.b.y})};
    auto index = [&](double v, double origin) { return static_cast<long long>(std::floor((v - origin) / cell)); };
    // Cell indices packed into one key, unsigned (a neighbour of the first cell has index −1;
    // shifting a negative number left is undefined).
    auto key = [](long long i, long long j) {
        return (static_cast<unsigned long long>(i) << 32) ^ (static_cast<unsigned long long>(j) & 0xffffffffULL);
    };
    std::unordered_map<unsigned long long, std::vector<int>> bins;
    for (std::size_t k = 0; k < edges.size(); ++k) {
        const Edge& e = edges[k];
        const long long i0 = index(std::min(e.a.x, e.b.x), low.x), i1 = index(std::max(e.a.x, e.b.x), low.x);
        const long long j0 = index(std::min(e.a.y, e.b.y), low.y), j1 = index(std::max(e.a.y, e.b.y), low.y);
        // A long edge crossing many cells is binned along its bounding box only when that box is
        // thin; otherwise cell by cell along the edge (with one cell of margin).
        if ((i1 - i0 + 1) * (j1 - j0 + 1) <= 64) {
            for (long long i = i0; i <= i1; ++i)
                for (long long j = j0; j <= j1; ++j) bins[key(i, j)].push_back(static_cast<int>(k));
            continue;
        }
        const double length = std::hypot(e.b.x - e.a.x, e.b.y - e.a.y);
        const int pieces = static_cast<int>(std::ceil(length / cell)) + 1;
        unsigned long long last = 0;
        bool any = false;
        for (int s = 0; s <= pieces; ++s) {
            const double t = static_cast<double>(s) / pieces;
            const long long i = index(e.a.x + t * (e.b.x - e.a.x), low.x), j = index(e.a.y + t * (e.b.y - e.a.y), low.y);
            for (long long di = -1; di <= 1; ++di)
                for (long long dj = -1; dj <= 1; ++dj) {
                    const unsigned long long kk = key(i + di, j + dj);
                    if (any && kk == last) continue;
                    auto& bin = bins[kk];
                    if (bin.empty() || bin.back() != static_cast<int>(k)) bin.push_back(static_cast<int>(k));
                }
            last = key(i, j);
            any = true;
        }
    }
    for (std::size_t r = 0; r < rings.size(); ++r) {
        const Ring& ring = *rings[r];
        for (int v = 0; v < static_cast<int>(ring.size()); ++v) {
            const Point2 p = ring[v];
            const long long i = index(p.x, low.x), j = index(p.y, low.y);
            for (long long di = -1; di <= 1; ++di)
                for (long long dj = -1; dj <= 1; ++dj) {
                    const auto it = bins.find(key(i + di, j + dj));
                    if (it == bins.end()) continue;
                    for (int k : it->second) {
                        const Edge& e = edges[k];
                        if (e.ring == static_cast<int>(r) && (e.from == v || e.to == v)) continue;
                        // The same point twice (a block pinched at a vertex) is topology, not a
                        // small feature.
                        if ((p.x == e.a.x && p.y == e.a.y) || (p.x == e.b.x && p.y == e.b.y)) continue;
                        const double d = distance_to_segment(p, e.a, e.b);
                        if (d < tolerance)
                            return SmallFeature{d, p, "a vertex " + metres(d) + " from an edge it does not end"};
                    }
                }
        }
    }
    return std::nullopt;
}

SharpCorner sharpest_corner(const Block& block) {
    SharpCorner sharpest;
    auto visit = [&](const Ring& ring) {
        const std::size_t n = ring.size();
        for (std::size_t i = 0; i < n; ++i) {
            const Point2& prev = ring[(i + n - 1) % n];
            const Point2& v = ring[i];
            const Point2& next = ring[(i + 1) % n];
            // The block lies left of its ring edges (outer CCW, holes CW): the interior angle is
            // π minus the left turn from the incoming to the outgoing edge.
            const double ix = v.x - prev.x, iy = v.y - prev.y, ox = next.x - v.x, oy = next.y - v.y;
            const double angle = 180.0 - std::atan2(ix * oy - iy * ox, ix * ox + iy * oy) * 180.0 / M_PI;
            if (angle < sharpest.angle_deg) sharpest = SharpCorner{angle, v};
        }
    };
    visit(block.outer);
    for (const Ring& h : block.holes) visit(h);
    return sharpest;
}

std::optional<SharpCorner> find_sharp_corner(const Block& block, double limit_deg) {
    const SharpCorner corner = sharpest_corner(block);
    if (corner.angle_deg < limit_deg) return corner;
    return std::nullopt;
}

void check_block_features(const Model& model, const std::vector<Block>& blocks, std::vector<Diagnostic>& diagnostics) {
    const auto box = model.bounds();
    const double size = std::hypot(box[2] - box[0], box[3] - box[1]);
    const double tolerance = smallest_block_feature_ratio * size;
    constexpr int reported = 5;
    int found = 0;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const Block& b = blocks[i];
        const auto feature = find_small_feature(b, tolerance);
        if (!feature) {
            const auto corner = find_sharp_corner(b, sharpest_corner_deg);
            if (!corner) continue;
            if (++found > reported) continue;
            std::ostringstream text;
            text.precision(3);
            text << "block " << i + 1 << " of region \"" << model.regions[b.region].name << "\" has a corner of "
                 << corner->angle_deg << "° at (";
            text.precision(9);
            text << corner->where.x << ", " << corner->where.y << ")";
            text.precision(3);
            text << ", sharper than " << sharpest_corner_deg
                 << "°: joints, or a joint and the region's boundary, meeting at so small an angle cut a sliver "
                    "that can be neither meshed nor held by contacts in bounded work; make them meet at a "
                    "larger angle, end one joint on the other, or leave one out";
            diagnostics.push_back({Diagnostic::Severity::Error, "/regions/" + std::to_string(b.region), text.str()});
            continue;
        }
        if (++found > reported) continue;
        std::ostringstream where;
        where.precision(9);
        where << "(" << feature->where.x << ", " << feature->where.y << ")";
        diagnostics.push_back(
            {Diagnostic::Severity::Error, "/regions/" + std::to_string(b.region),
             "block " + std::to_string(i + 1) + " of region \"" + model.regions[b.region].name + "\" has " +
                 feature->what + " near " + where.str() + ", below " + metres(tolerance) +
                 " (a hundred-thousandth of the model's size), which cannot be meshed: a sliver of a region, "
                 "nearly coincident vertices or joints, or a joint passing a hair's breadth from a "
                 "vertex; move the vertex or the joint"});
    }
    if (found > reported) {
        std::ostringstream text;
        text << found - reported << " more blocks have features below " << metres(tolerance)
             << " or corners sharper than " << sharpest_corner_deg << "°";
        diagnostics.push_back({Diagnostic::Severity::Error, "/regions", text.str()});
    }
}

}  // namespace mcdda
