// 3D arithmetic for the scene pipeline: vectors, rotations, and sine and cosine of degrees. Plain
// double arithmetic only (+, -, *, / and the correctly rounded square root), no libm: the kernel's
// x87 at 53-bit precision and the host's SSE2 compute the same bits, so a frame's geometry is the
// same on both sides of the serial line.
#pragma once

#include <stdint.h>

#include "kernel/core/fixed.h"

namespace raster {

struct Vec3 {
    double x = 0, y = 0, z = 0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return Vec3{a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return Vec3{a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double k, Vec3 a) { return Vec3{k * a.x, k * a.y, k * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) { return Vec3{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// The correctly rounded square root (SSE2 sqrtsd, x87 fsqrt at 53-bit precision); x >= 0.
inline double square_root(double x) { return __builtin_sqrt(x); }

inline double length(Vec3 a) { return square_root(dot(a, a)); }
// a / |a|; the zero vector stays zero.
inline Vec3 normalize(Vec3 a) {
    double n = length(a);
    return n > 0 ? Vec3{a.x / n, a.y / n, a.z / n} : a;
}
inline Vec3 lerp(Vec3 a, Vec3 b, double t) { return a + t * (b - a); }

// sin and cos of an angle in degrees. The angle is reduced to [0, 360) and then to an octant, so
// multiples of 90 degrees give exact 0 and +-1; within the octant, Taylor series to the 17th
// power (|x| <= pi/4: the first term dropped is below 2^-60 of the result).
inline void sin_cos_degrees(double degrees, double* s, double* c) {
    constexpr double RADIANS_PER_DEGREE = 3.14159265358979323846 / 180.0;
    double r = degrees - 360.0 * double(floor_i64(degrees / 360.0));
    if (r < 0) r += 360.0;  // rounding at the edges of the reduction
    if (r >= 360.0) r -= 360.0;
    int quadrant = int(r / 90.0);
    if (quadrant > 3) quadrant = 3;
    double a = r - 90.0 * quadrant;  // [0, 90]
    bool swap = a > 45.0;
    if (swap) a = 90.0 - a;
    double x = a * RADIANS_PER_DEGREE, x2 = x * x;
    // sin x = x - x^3/3! + ...; cos x = 1 - x^2/2! + ... (Horner, from the smallest term)
    double sn = x * (1 - x2 / 6 * (1 - x2 / 20 * (1 - x2 / 42 * (1 - x2 / 72 * (1 - x2 / 110 * (1 - x2 / 156 * (1 - x2 / 210 * (1 - x2 / 272))))))));
    double cs = 1 - x2 / 2 * (1 - x2 / 12 * (1 - x2 / 30 * (1 - x2 / 56 * (1 - x2 / 90 * (1 - x2 / 132 * (1 - x2 / 182 * (1 - x2 / 240)))))));
    if (swap) {
        double t = sn;
        sn = cs;
        cs = t;
    }
    switch (quadrant) {
    case 0: *s = sn, *c = cs; break;
    case 1: *s = cs, *c = -sn; break;
    case 2: *s = -sn, *c = -cs; break;
    default: *s = -cs, *c = sn; break;
    }
}

// A rotation (row-major 3x3) by `degrees` about `axis` (normalized here; a zero axis: no rotation),
// counter-clockwise seen from the axis's tip (right-handed).
struct Rotation {
    double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

    static Rotation about(Vec3 axis, double degrees) {
        Rotation r;
        Vec3 k = normalize(axis);
        if (k.x == 0 && k.y == 0 && k.z == 0) return r;
        double s, c;
        sin_cos_degrees(degrees, &s, &c);
        double t = 1 - c;
        r.m[0][0] = c + t * k.x * k.x, r.m[0][1] = t * k.x * k.y - s * k.z, r.m[0][2] = t * k.x * k.z + s * k.y;
        r.m[1][0] = t * k.y * k.x + s * k.z, r.m[1][1] = c + t * k.y * k.y, r.m[1][2] = t * k.y * k.z - s * k.x;
        r.m[2][0] = t * k.z * k.x - s * k.y, r.m[2][1] = t * k.z * k.y + s * k.x, r.m[2][2] = c + t * k.z * k.z;
        return r;
    }

    Vec3 apply(Vec3 p) const {
        return Vec3{(m[0][0] * p.x + m[0][1] * p.y) + m[0][2] * p.z, (m[1][0] * p.x + m[1][1] * p.y) + m[1][2] * p.z,
                    (m[2][0] * p.x + m[2][1] * p.y) + m[2][2] * p.z};
    }

    // this after `first`: (this * first) p = this(first(p))
    Rotation after(const Rotation& first) const {
        Rotation r;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) r.m[i][j] = (m[i][0] * first.m[0][j] + m[i][1] * first.m[1][j]) + m[i][2] * first.m[2][j];
        return r;
    }
};

}  // namespace raster
