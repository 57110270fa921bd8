/*
 * Rasterization rules of ES 1.1 §3.3-3.5, through the GL API, on a 288 x 288 surface (large
 * enough for the widest point or line Mesa allows, 255):
 *
 * - polygons (§3.5.1): point sampling at pixel centers (x + 0.5, y + 0.5), and a fragment
 *   whose center lies on an edge shared by two polygons is produced by exactly one of them.
 *   Checked with additive blending (GL_ONE, GL_ONE) of color 0.25 (64 in 8 bits): every pixel
 *   of a covered region is exactly 64 (never hit twice, no gap), for quads split along a
 *   diagonal, edges through pixel centers, fans, strips and a random mesh. Vertices lie on a
 *   1/16 grid, so snapping to the subpixel grid (8 bits here and on llvmpipe, 4 on softpipe)
 *   moves nothing and the coverage of every pixel center is exact arithmetic;
 * - slivers and subpixel triangles: a triangle covering no pixel center draws nothing, one
 *   covering one center draws exactly that pixel;
 * - flat shading (§2.14.7, table 2.8): the color of each triangle (strips, fans, lists) and
 *   line segment is that of its last vertex;
 * - aliased lines (§3.4.1): the diamond-exit rule. The specification allows approximations
 *   (fragments within one pixel of the ideal ones, at most one fragment more or fewer, one
 *   fragment per column of an x-major segment, and no fragment doubled or dropped where
 *   connected segments of the same major axis meet). Every implementation is held to those
 *   allowances; the ideal fragments themselves (start pixel in, end pixel out, segments on
 *   pixel boundaries moved by the (eps, eps^2) perturbation to the lower/left side) only on
 *   our library. Wide lines (§3.4.2): the width rounds to an integer (0 -> 1) and each
 *   fragment becomes a column (x-major) or row (y-major) of that many pixels, centered on the
 *   segment;
 * - aliased points (§3.3): the size rounds to an integer; odd sizes are the square centered
 *   on the center of the pixel holding the vertex, even sizes the square centered on the
 *   pixel corner nearest the vertex;
 * - smooth points and lines (GL_POINT_SMOOTH, GL_LINE_SMOOTH): each fragment's alpha is the
 *   covered share of its pixel, so with blending (GL_SRC_ALPHA, GL_ONE) of white the sum of the
 *   red channel / 255 approximates the area (pi r^2 for a point, width x length for a line).
 *   The specification lets implementations approximate coverage, so the sum is allowed 10 %
 *   (a ring of 1/16-pixel error around a radius-4 disc is already 3 %); a pixel fully inside
 *   must be fully covered (255);
 * - the GL_ALIASED_* and GL_SMOOTH_* size ranges: a size above the queried maximum is clamped
 *   to it.
 */
#include "common.h"

#include <math.h>

#define PI 3.14159265358979323846

#define W 288
#define H 288

static GLubyte fb[W * H * 4];

static void grab(void)
{
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, fb);
}

/* Red channel of pixel (x, y) of the last grab, 0 outside the surface. */
static int red(int x, int y)
{
    if (x < 0 || y < 0 || x >= W || y >= H)
        return 0;
    return fb[4 * (y * W + x)];
}

static int failures_before;

static void begin(void)
{
    failures_before = ct.failures;
}

static void done(const char *what)
{
    if (ct.failures > failures_before)
        fprintf(stderr, "  ^ in: %s\n", what);
}

/* Counts a check of `cond`, naming `what` (with numbers) when it fails. */
static void expect(int cond, const char *what, int a, int b)
{
    char m[200];
    ++ct.checks;
    if (!cond) {
        snprintf(m, sizeof m, "%s (%d, %d)", what, a, b);
        ct_fail(__FILE__, __LINE__, m);
    }
}

static void fresh(void)
{
    glDisable(GL_BLEND);
    glDisable(GL_POINT_SMOOTH);
    glDisable(GL_LINE_SMOOTH);
    glShadeModel(GL_SMOOTH);
    glDisableClientState(GL_COLOR_ARRAY);
    glLineWidth(1);
    glPointSize(1);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
}

static void additive(void)
{
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glColor4f(0.25f, 0.25f, 0.25f, 0.25f);
}

static void draw(GLenum mode, const GLfloat *v, int n)
{
    glVertexPointer(2, GL_FLOAT, 0, v);
    glDrawArrays(mode, 0, n);
}

/* Every pixel of [x0, x1) x [y0, y1) is 64 and the 2-pixel ring around it is 0. Returns the
 * number of wrong pixels. */
static int check_region(int x0, int y0, int x1, int y1, const char *what)
{
    int x, y, bad_in = 0, bad_out = 0;
    for (y = y0 - 2; y < y1 + 2; ++y) {
        for (x = x0 - 2; x < x1 + 2; ++x) {
            int inside = x >= x0 && x < x1 && y >= y0 && y < y1;
            int r = red(x, y);
            if (inside && r != 64)
                ++bad_in;
            if (!inside && r != 0)
                ++bad_out;
        }
    }
    expect(bad_in == 0, what, bad_in, 64);
    expect(bad_out == 0, what, bad_out, 0);
    return bad_in + bad_out;
}

/* A deterministic pseudo-random number in [0, 1). */
static unsigned rng_state = 12345;
static double rnd(void)
{
    rng_state = rng_state * 1103515245u + 12345u;
    return (double)((rng_state >> 8) & 0xFFFF) / 65536.0;
}

/* Rounds to the 1/16 grid. */
static GLfloat g16(double v)
{
    return (GLfloat)(floor(v * 16 + 0.5) / 16);
}

/* ---------------------------------------------------------------- polygons */

static void test_fill_rules(void)
{
    /* Two triangles sharing each diagonal of integer squares. */
    static const GLfloat sq1[12] = {8, 8, 40, 8, 40, 40, 8, 8, 40, 40, 8, 40};
    static const GLfloat sq2[12] = {48, 8, 80, 8, 48, 40, 80, 8, 80, 40, 48, 40};
    /* A 2 x 2 block of squares whose every edge runs through pixel centers, each split along
     * a diagonal (also through centers), drawn as 8 triangles. */
    GLfloat grid[96];
    int n = 0, i, j, x, y, bad;
    /* A quad with vertices on the 1/16 grid, split along a slanted diagonal. */
    static const GLfloat q[8] = {100.25f, 8.75f, 140.125f, 12.1875f, 135.5625f, 47.875f,
                                 102.1875f, 40.4375f};
    GLfloat qt[12];

    begin();
    fresh();
    additive();
    draw(GL_TRIANGLES, sq1, 6);
    draw(GL_TRIANGLES, sq2, 6);
    for (j = 0; j < 2; ++j) {
        for (i = 0; i < 2; ++i) {
            GLfloat x0 = 150.5f + 16 * (GLfloat)i, y0 = 8.5f + 16 * (GLfloat)j;
            GLfloat x1 = x0 + 16, y1 = y0 + 16;
            GLfloat t[12];
            t[0] = x0, t[1] = y0, t[2] = x1, t[3] = y0, t[4] = x1, t[5] = y1;
            t[6] = x0, t[7] = y0, t[8] = x1, t[9] = y1, t[10] = x0, t[11] = y1;
            if ((i + j) % 2) { /* the other diagonal */
                t[4] = x0, t[5] = y1, t[6] = x1, t[7] = y0;
                t[8] = x1, t[9] = y1, t[10] = x0, t[11] = y1;
            }
            memcpy(grid + n, t, sizeof t);
            n += 12;
        }
    }
    draw(GL_TRIANGLES, grid, n / 2);
    qt[0] = q[0], qt[1] = q[1], qt[2] = q[2], qt[3] = q[3], qt[4] = q[4], qt[5] = q[5];
    qt[6] = q[0], qt[7] = q[1], qt[8] = q[4], qt[9] = q[5], qt[10] = q[6], qt[11] = q[7];
    draw(GL_TRIANGLES, qt, 6);
    CHECK_GL(GL_NO_ERROR);
    grab();
    check_region(8, 8, 40, 40, "two triangles sharing a diagonal: bad pixels");
    check_region(48, 8, 80, 40, "two triangles sharing the other diagonal: bad pixels");
    /* The 2 x 2 block: its interior (centers strictly inside [150.5, 182.5)^2) is exactly
     * 64, including the shared edges through centers; on its outer edges, which also pass
     * through centers, the specification leaves the choice open: 0 or 64. */
    bad = 0;
    for (y = 4; y < 46; ++y) {
        for (x = 146; x < 188; ++x) {
            int r = red(x, y);
            int inner = x >= 151 && x <= 181 && y >= 9 && y <= 39;
            int edge = (x == 150 || x == 182) && y >= 8 && y <= 40;
            edge = edge || ((y == 8 || y == 40) && x >= 150 && x <= 182);
            if (inner ? r != 64 : edge ? r != 0 && r != 64 : r != 0)
                ++bad;
        }
    }
    expect(bad == 0, "edges through pixel centers: bad pixels", bad, 0);
    /* The slanted quad: centers clearly inside (by 1/64 of a pixel, more than any rounding
     * of exact grid arithmetic could move) are 64, clearly outside 0, none above 64. */
    {
        int over = 0, in_bad = 0, out_bad = 0;
        for (y = 4; y < 52; ++y) {
            for (x = 96; x < 144; ++x) {
                double px = x + 0.5, py = y + 0.5, dmin = 1e9;
                int k, inside = 1, r = red(x, y);
                for (k = 0; k < 4; ++k) {
                    double ax = q[2 * k], ay = q[2 * k + 1];
                    double bx = q[(2 * k + 2) % 8], by = q[(2 * k + 3) % 8];
                    double len = sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay));
                    double d = ((bx - ax) * (py - ay) - (by - ay) * (px - ax)) / len;
                    if (d < 0)
                        inside = 0;
                    if (fabs(d) < dmin)
                        dmin = fabs(d);
                }
                over += r > 64;
                if (dmin > 1.0 / 64) {
                    in_bad += inside && r != 64;
                    out_bad += !inside && r != 0;
                }
            }
        }
        expect(over == 0 && in_bad == 0 && out_bad == 0,
               "slanted shared edge: pixels over 64, wrong inside", over, in_bad + out_bad);
    }
    done("fill rule");
    ct_save("fill_rule");
}

static void test_watertight(void)
{
    /* A fan around (40, 120) over the boundary of [8, 72) x [100, 140), corners included, and
     * a strip over [8, 72) x [150, 190) with its vertices at random places along the edges,
     * and a 9 x 9-vertex mesh over [100, 228) x [100, 228) with its inner vertices moved at
     * random (edges cross pixel centers at every angle). */
    GLfloat fan[2 * 40], strip[2 * 40], mesh[2 * 8 * 8 * 6];
    GLfloat mv[9][9][2];
    int n, i, j, k;
    static const GLfloat corners[4][2] = {{72, 100}, {72, 140}, {8, 140}, {8, 100}};
    GLfloat bx, tx;

    begin();
    fresh();
    additive();
    /* Fan: center, then around the rectangle counter-clockwise from (8, 100). */
    n = 0;
    fan[n++] = g16(40.3), fan[n++] = g16(121.7);
    fan[n++] = 8, fan[n++] = 100;
    for (k = 0; k < 4; ++k) {
        /* 4 random points strictly along the side ending at corners[k], then the corner */
        GLfloat sx = fan[n - 2], sy = fan[n - 1];
        for (i = 1; i <= 4; ++i) {
            double t = (i - 1 + 0.2 + 0.6 * rnd()) / 4;
            fan[n++] = g16(sx + (corners[k][0] - sx) * t);
            fan[n++] = g16(sy + (corners[k][1] - sy) * t);
        }
        fan[n++] = corners[k][0], fan[n++] = corners[k][1];
    }
    draw(GL_TRIANGLE_FAN, fan, n / 2);
    /* Strip: bottom and top vertices alternating, x increasing on each edge. */
    n = 0;
    bx = tx = 8;
    strip[n++] = 8, strip[n++] = 150, strip[n++] = 8, strip[n++] = 190;
    for (i = 0; i < 9; ++i) {
        bx = i == 8 ? 72 : g16(bx + 2 + 8 * rnd());
        tx = i == 8 ? 72 : g16(tx + 2 + 8 * rnd());
        if (bx > 72)
            bx = 72;
        if (tx > 72)
            tx = 72;
        strip[n++] = bx, strip[n++] = 150, strip[n++] = tx, strip[n++] = 190;
    }
    draw(GL_TRIANGLE_STRIP, strip, n / 2);
    /* Mesh. */
    for (j = 0; j < 9; ++j) {
        for (i = 0; i < 9; ++i) {
            double x = 100 + 16 * i, y = 100 + 16 * j;
            if (i > 0 && i < 8)
                x += 14 * (rnd() - 0.5);
            if (j > 0 && j < 8)
                y += 14 * (rnd() - 0.5);
            mv[j][i][0] = g16(x);
            mv[j][i][1] = g16(y);
        }
    }
    n = 0;
    for (j = 0; j < 8; ++j) {
        for (i = 0; i < 8; ++i) {
            const GLfloat *a = mv[j][i], *b = mv[j][i + 1], *c = mv[j + 1][i + 1],
                          *d = mv[j + 1][i];
            const GLfloat *order[6];
            if (rnd() < 0.5) {
                order[0] = a, order[1] = b, order[2] = c, order[3] = a, order[4] = c,
                order[5] = d;
            } else { /* the other diagonal, and clockwise */
                order[0] = a, order[1] = d, order[2] = b, order[3] = b, order[4] = d,
                order[5] = c;
            }
            for (k = 0; k < 6; ++k) {
                mesh[n++] = order[k][0];
                mesh[n++] = order[k][1];
            }
        }
    }
    draw(GL_TRIANGLES, mesh, n / 2);
    CHECK_GL(GL_NO_ERROR);
    grab();
    check_region(8, 100, 72, 140, "fan: bad pixels");
    check_region(8, 150, 72, 190, "strip: bad pixels");
    check_region(100, 100, 228, 228, "random mesh: bad pixels");
    done("watertight fans, strips and meshes");
    ct_save("watertight");
}

static void test_slivers(void)
{
    /* Inside pixel (200, 240), missing its center. */
    static const GLfloat tiny[6] = {200.0625f, 240.0625f, 200.375f, 240.0625f, 200.0625f,
                                    240.375f};
    /* Inside pixel (210, 240), around its center. */
    static const GLfloat dot[6] = {210.25f, 240.25f, 210.875f, 240.375f, 210.375f, 240.875f};
    /* Between the rows of centers 250.5 and 251.5, 60 pixels long. */
    static const GLfloat sliver[6] = {10, 250.625f, 70, 250.75f, 10, 250.875f};
    /* Over centers y = 260.5 for x > 42 only: its height at x is (x - 10) / 512. */
    static const GLfloat wedge[6] = {10, 260.4375f, 74, 260.4375f, 74, 260.5625f};
    /* Degenerate: zero area. */
    static const GLfloat flat[6] = {100, 250.5f, 140, 250.5f, 120, 250.5f};
    int x, y, lit = 0, lit_row = 0, x0 = 1000, x1 = -1;

    begin();
    fresh();
    glColor4f(1, 1, 1, 1);
    draw(GL_TRIANGLES, tiny, 3);
    draw(GL_TRIANGLES, dot, 3);
    draw(GL_TRIANGLES, sliver, 3);
    draw(GL_TRIANGLES, wedge, 3);
    draw(GL_TRIANGLES, flat, 3);
    CHECK_GL(GL_NO_ERROR);
    grab();
    for (y = 236; y < 266; ++y) {
        for (x = 0; x < 220; ++x) {
            if (red(x, y) == 0)
                continue;
            if (y == 260) {
                ++lit_row;
                x0 = x < x0 ? x : x0;
                x1 = x > x1 ? x : x1;
            } else {
                ++lit;
            }
        }
    }
    for (y = 238; y <= 242; ++y)
        for (x = 198; x <= 212; ++x)
            if (!(x == 210 && y == 240))
                expect(red(x, y) == 0, "subpixel triangle covering no center drew", x, y);
    expect(red(210, 240) == 255, "subpixel triangle over one center", 210, 240);
    expect(lit == 1, "lit pixels outside the wedge row (only the dot expected)", lit, 1);
    expect(lit_row == 32 && x0 == 42 && x1 == 73, "wedge row: count, first", lit_row, x0);
    done("slivers and subpixel triangles");
}

/* ---------------------------------------------------------------- flat shading */

static void test_flat_shading(void)
{
    static const GLubyte colors[6][4] = {{255, 0, 0, 255},   {0, 255, 0, 255},
                                         {0, 0, 255, 255},   {255, 255, 0, 255},
                                         {0, 255, 255, 255}, {255, 0, 255, 255}};
    /* Strip and fan of 4 vertices (2 triangles), a list of 2 triangles (6 vertices). */
    static const GLfloat strip[8] = {10, 10, 40, 10, 10, 40, 40, 40};
    static const GLfloat fan[8] = {50, 10, 80, 10, 80, 40, 50, 40};
    static const GLfloat list[12] = {90, 10, 120, 10, 120, 40, 90, 10, 120, 40, 90, 40};
    /* A line strip of 3 vertices, two separate lines. */
    static const GLfloat lstrip[6] = {10.5f, 60.5f, 30.5f, 60.5f, 50.5f, 60.5f};
    static const GLfloat lines[8] = {60.5f, 60.5f, 80.5f, 60.5f, 90.5f, 60.5f, 110.5f, 60.5f};

    begin();
    fresh();
    glShadeModel(GL_FLAT);
    glEnableClientState(GL_COLOR_ARRAY);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    draw(GL_TRIANGLE_STRIP, strip, 4);
    draw(GL_TRIANGLE_FAN, fan, 4);
    draw(GL_TRIANGLES, list, 6);
    draw(GL_LINE_STRIP, lstrip, 3);
    draw(GL_LINES, lines, 4);
    glDisableClientState(GL_COLOR_ARRAY);
    CHECK_GL(GL_NO_ERROR);
    /* Strip: (v0 v1 v2) below the diagonal from (40, 10) to (10, 40) takes v2 (blue);
     * (v1 v2 v3) above it takes v3 (yellow). */
    CHECK_PIXEL(15, 15, 0, 0, 255, 255, 0);
    CHECK_PIXEL(35, 35, 255, 255, 0, 255, 0);
    /* Fan: (v0 v1 v2) below the diagonal (50, 10)-(80, 40) takes v2, (v0 v2 v3) v3. */
    CHECK_PIXEL(75, 15, 0, 0, 255, 255, 0);
    CHECK_PIXEL(55, 35, 255, 255, 0, 255, 0);
    /* List: triangles take v2 (blue) and v5 (magenta). */
    CHECK_PIXEL(115, 15, 0, 0, 255, 255, 0);
    CHECK_PIXEL(95, 35, 255, 0, 255, 255, 0);
    /* Line strip: segments take v1 (green) and v2 (blue); lines v1 (green) and v3 (yellow). */
    CHECK_PIXEL(20, 60, 0, 255, 0, 255, 0);
    CHECK_PIXEL(40, 60, 0, 0, 255, 255, 0);
    CHECK_PIXEL(70, 60, 0, 255, 0, 255, 0);
    CHECK_PIXEL(100, 60, 255, 255, 0, 255, 0);
    done("flat shading provoking vertex");
    ct_save("flat_shading");
    glShadeModel(GL_SMOOTH);
}

/* ---------------------------------------------------------------- aliased lines */

/* The lit pixels (red != 0) of the box [x0, x1] x [y0, y1] of the last grab. */
struct lit {
    int count, xmin, xmax, ymin, ymax, over, per_col_max, per_row_max;
};

static struct lit scan(int x0, int y0, int x1, int y1)
{
    struct lit l;
    int x, y;
    l.count = 0, l.xmin = l.ymin = 1 << 20, l.xmax = l.ymax = -1, l.over = 0;
    l.per_col_max = l.per_row_max = 0;
    for (x = x0; x <= x1; ++x) {
        int c = 0;
        for (y = y0; y <= y1; ++y)
            c += red(x, y) != 0;
        l.per_col_max = c > l.per_col_max ? c : l.per_col_max;
    }
    for (y = y0; y <= y1; ++y) {
        int c = 0;
        for (x = x0; x <= x1; ++x) {
            int r = red(x, y);
            if (!r)
                continue;
            ++c;
            ++l.count;
            l.over += r > 64;
            l.xmin = x < l.xmin ? x : l.xmin;
            l.xmax = x > l.xmax ? x : l.xmax;
            l.ymin = y < l.ymin ? y : l.ymin;
            l.ymax = y > l.ymax ? y : l.ymax;
        }
        l.per_row_max = c > l.per_row_max ? c : l.per_row_max;
    }
    return l;
}

/* An x-major (or y-major) 1-pixel segment whose ideal fragments are the pixels with major
 * coordinate first..last (inclusive, in either order) on minor coordinate `minor`, drawn
 * alone, scanned within 2 pixels. Every implementation: within one pixel of the ideal ones,
 * count within one, one per column (row). Ours: exactly the ideal ones. */
static void check_segment(const GLfloat *v, int x_major, int first, int last, int minor,
                          const char *what)
{
    int lo = first < last ? first : last, hi = first < last ? last : first;
    int n = hi - lo + 1;
    struct lit l;
    fresh();
    glColor4f(1, 1, 1, 1);
    draw(GL_LINES, v, 2);
    grab();
    if (x_major)
        l = scan(lo - 3, minor - 3, hi + 3, minor + 3);
    else
        l = scan(minor - 3, lo - 3, minor + 3, hi + 3);
    {
        int mj0 = x_major ? l.xmin : l.ymin, mj1 = x_major ? l.xmax : l.ymax;
        int mn0 = x_major ? l.ymin : l.xmin, mn1 = x_major ? l.ymax : l.xmax;
        int per = x_major ? l.per_col_max : l.per_row_max;
        expect(l.count >= n - 1 && l.count <= n + 1, what, l.count, n);
        expect(mj0 >= lo - 1 && mj1 <= hi + 1 && mn0 >= minor - 1 && mn1 <= minor + 1, what,
               mj0, mn0);
        expect(per == 1, what, per, 1);
        if (ct_strict()) {
            expect(l.count == n && mj0 == lo && mj1 == hi && mn0 == minor && mn1 == minor,
                   what, mj0 * 1000 + mj1, mn0 * 1000 + mn1);
        }
    }
}

static void test_lines(void)
{
    static const GLfloat h[4] = {4.5f, 150.5f, 12.5f, 150.5f};
    static const GLfloat h_rev[4] = {12.5f, 150.5f, 4.5f, 150.5f};
    static const GLfloat v[4] = {20.5f, 140.5f, 20.5f, 148.5f};
    static const GLfloat diag[4] = {4.5f, 160.5f, 12.5f, 168.5f};
    /* On the boundary between rows 179 and 180, and between columns 19 and 20. */
    static const GLfloat h_edge[4] = {4.5f, 180, 12.5f, 180};
    static const GLfloat v_edge[4] = {20, 170.5f, 20, 178.5f};
    /* A line strip of x-major segments left to right, and one of y-major ones bottom to
     * top, for the additive no-double, no-gap check at the joints. */
    static const GLfloat xs[8] = {30.5f, 150.5f, 40.5f, 150.5f, 50.25f, 155.75f, 60.5f,
                                  158.5f};
    static const GLfloat ys[8] = {70.5f, 140.5f, 70.5f, 150.5f, 75.75f, 160.25f, 78.5f,
                                  170.5f};
    /* Width tests: x-major and y-major segments. */
    static const GLfloat wh[4] = {100.5f, 150.5f, 120.5f, 150.5f};
    static const GLfloat wv[4] = {150.5f, 140.5f, 150.5f, 160.5f};
    GLfloat range[2], big[4];
    int x, y, bad;
    struct lit l;

    begin();
    /* x-major from pixel center (4, 150) to pixel center (12, 150): (4..11, 150). */
    check_segment(h, 1, 4, 11, 150, "horizontal segment center to center");
    /* Reversed: starts in pixel 12, ends in 4: (12..5, 150). */
    check_segment(h_rev, 1, 12, 5, 150, "reversed horizontal segment");
    check_segment(v, 0, 140, 147, 20, "vertical segment center to center");
    /* Diagonal (slope 1 is x-major): ideally (4, 160) .. (11, 167), not (12, 168). Every
     * implementation: one fragment per column, each within one pixel of the diagonal, 7 to
     * 9 of them. */
    fresh();
    glColor4f(1, 1, 1, 1);
    draw(GL_LINES, diag, 2);
    grab();
    l = scan(0, 155, 17, 173);
    bad = 0;
    for (y = 155; y <= 173; ++y)
        for (x = 0; x <= 17; ++x)
            bad += red(x, y) != 0 && (x < 3 || x > 12 || abs(y - (160 + x - 4)) > 1);
    expect(bad == 0 && l.per_col_max == 1 && l.count >= 7 && l.count <= 9,
           "diagonal segment: stray pixels, count", bad, l.count);
    if (ct_strict()) {
        expect(l.count == 8 && red(4, 160) && red(11, 167) && !red(12, 168), "diagonal ends",
               l.count, 8);
        for (x = 4; x < 12; ++x)
            expect(red(x, 160 + x - 4) != 0, "diagonal pixel", x, 160 + x - 4);
    }
    /* The (eps, eps^2) perturbation moves a segment along y = 180 below it (row 179) and
     * one along x = 20 to the left (column 19). */
    check_segment(h_edge, 1, 4, 11, 179, "horizontal segment on a pixel boundary");
    check_segment(v_edge, 0, 170, 177, 19, "vertical segment on a pixel boundary");
    done("single aliased segments");

    /* Strips under additive blending: no pixel hit twice, and each column (row) between the
     * ends has exactly one fragment (§3.4.1's condition on connected segments). */
    begin();
    fresh();
    additive();
    draw(GL_LINE_STRIP, xs, 4);
    draw(GL_LINE_STRIP, ys, 4);
    CHECK_GL(GL_NO_ERROR);
    grab();
    l = scan(26, 146, 64, 162);
    expect(l.over == 0 && l.per_col_max == 1, "x-major strip: over 64, per column", l.over,
           l.per_col_max);
    bad = 0;
    for (x = 31; x < 60; ++x) {
        int c = 0;
        for (y = 146; y <= 162; ++y)
            c += red(x, y) == 64;
        bad += c != 1;
    }
    expect(bad == 0, "x-major strip: columns without exactly one fragment", bad, 0);
    if (ct_strict())
        expect(l.count == 30 && l.xmin == 30 && l.xmax == 59, "x-major strip: count, first",
               l.count, l.xmin);
    l = scan(66, 136, 82, 174);
    expect(l.over == 0 && l.per_row_max == 1, "y-major strip: over 64, per row", l.over,
           l.per_row_max);
    bad = 0;
    for (y = 141; y < 170; ++y) {
        int c = 0;
        for (x = 66; x <= 82; ++x)
            c += red(x, y) == 64;
        bad += c != 1;
    }
    expect(bad == 0, "y-major strip: rows without exactly one fragment", bad, 0);
    if (ct_strict())
        expect(l.count == 30 && l.ymin == 140 && l.ymax == 169, "y-major strip: count, first",
               l.count, l.ymin);
    done("line strips");
    ct_save("line_strips");

    /* Wide lines. Width 3: rows 149..151 (a column of 3 centered on y = 150.5). */
    begin();
    fresh();
    glColor4f(1, 1, 1, 1);
    glLineWidth(3);
    draw(GL_LINES, wh, 2);
    draw(GL_LINES, wv, 2);
    CHECK_GL(GL_NO_ERROR);
    grab();
    ct_save("wide_lines");
    for (x = 101; x < 120; ++x) {
        for (y = 147; y <= 153; ++y) {
            int want = y >= 149 && y <= 151;
            expect((red(x, y) != 0) == want, "width-3 x-major column", x, y);
        }
    }
    for (y = 141; y < 160; ++y) {
        for (x = 147; x <= 153; ++x) {
            int want = x >= 149 && x <= 151;
            expect((red(x, y) != 0) == want, "width-3 y-major row", x, y);
        }
    }
    if (ct_strict()) {
        l = scan(96, 146, 124, 154);
        expect(l.count == 60 && l.xmin == 100 && l.xmax == 119, "width-3 segment", l.count,
               l.xmin);
    }
    /* Rounding: 2.4 -> 2, 2.6 -> 3, 0.3 -> 0 -> 1 (each column of the x-major segment). For
     * width 2 the segment moves down by 1/2 onto y = 150, a boundary, which the perturbation
     * gives to row 149: rows 149 and 150. */
    {
        static const GLfloat widths[3] = {2.4f, 2.6f, 0.3f};
        static const int rows[3] = {2, 3, 1};
        int k;
        for (k = 0; k < 3; ++k) {
            fresh();
            glColor4f(1, 1, 1, 1);
            glLineWidth(widths[k]);
            draw(GL_LINES, wh, 2);
            grab();
            l = scan(96, 140, 124, 160);
            if (k == 0) {
                /* softpipe widens the segment by 2.4 without rounding: 3 rows. */
                CHECK_MESA_DEVIATES(l.per_col_max == 2 && l.count >= 38 && l.count <= 42,
                                    "softpipe does not round aliased line widths");
            } else {
                expect(l.per_col_max == rows[k] && l.count >= rows[k] * 19 &&
                           l.count <= rows[k] * 21,
                       "line width rounding: column height, count", l.per_col_max, l.count);
            }
            if (k == 0 && ct_strict())
                expect(l.ymin == 149 && l.ymax == 150, "width-2 rows", l.ymin, l.ymax);
        }
    }
    /* A width above the aliased maximum is clamped to it. */
    glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, range);
    CHECK(range[0] <= 1 && range[1] >= 1);
    fresh();
    glColor4f(1, 1, 1, 1);
    glLineWidth(range[1] + 10);
    big[0] = 100.5f, big[1] = 144.5f, big[2] = 140.5f, big[3] = 144.5f;
    draw(GL_LINES, big, 2);
    grab();
    {
        int want = (int)floor(range[1] + 0.5);
        l = scan(96, 0, 144, H - 1);
        expect(want > H - 8 || l.per_col_max == want, "clamped line width: height, max",
               l.per_col_max, want);
    }
    CHECK_GL(GL_NO_ERROR);
    done("wide lines");
}

/* ---------------------------------------------------------------- aliased points */

static void test_points(void)
{
    /* size, position, the lower-left pixel of the expected square */
    static const struct {
        GLfloat size, x, y;
        int x0, y0, n;
    } pts[7] = {
        {1, 10.3f, 10.7f, 10, 10, 1},
        {2, 20.3f, 10.7f, 19, 10, 2}, /* nearest corner (20, 11) */
        {3, 30.3f, 10.7f, 29, 9, 3},  /* pixel (30, 10)'s center */
        {4, 40.7f, 10.2f, 39, 8, 4},  /* corner (41, 10) */
        {5, 50.9f, 10.1f, 48, 8, 5},  /* pixel (50, 10) */
        {2.4f, 60.6f, 10.6f, 60, 10, 2},
        {0.2f, 70.5f, 10.5f, 70, 10, 1}, /* rounds to 0: size 1 */
    };
    GLfloat range[2], p[2];
    int k, x, y;

    begin();
    for (k = 0; k < 7; ++k) {
        int bad = 0;
        fresh();
        glColor4f(1, 1, 1, 1);
        glPointSize(pts[k].size);
        p[0] = pts[k].x, p[1] = pts[k].y;
        draw(GL_POINTS, p, 1);
        grab();
        for (y = 0; y < 24; ++y) {
            for (x = pts[k].x0 - 6; x < pts[k].x0 + 12; ++x) {
                int in = x >= pts[k].x0 && x < pts[k].x0 + pts[k].n && y >= pts[k].y0 &&
                         y < pts[k].y0 + pts[k].n;
                bad += (red(x, y) != 0) != in;
            }
        }
        /* softpipe puts the square of size 2 at x 20.3 on columns 20-21 (the nearest corner
         * is x = 20) and that of size 5 at x 50.9 on columns 49-53 (the pixel holding it is
         * 50). */
        if (bad)
            fprintf(stderr, "point %d: %d wrong pixels\n", k, bad);
        CHECK_MESA_DEVIATES(bad == 0, "softpipe places some aliased points one pixel off");
    }
    /* A size above the aliased maximum is clamped to it. */
    glGetFloatv(GL_ALIASED_POINT_SIZE_RANGE, range);
    CHECK(range[0] <= 1 && range[1] >= 1);
    fresh();
    glColor4f(1, 1, 1, 1);
    glPointSize(range[1] + 10);
    p[0] = 144.5f, p[1] = 144.5f;
    draw(GL_POINTS, p, 1);
    grab();
    {
        int want = (int)floor(range[1] + 0.5);
        struct lit l = scan(0, 0, W - 1, H - 1);
        expect(want > H - 8 || (l.count == want * want && l.xmax - l.xmin + 1 == want),
               "clamped point size: count, max", l.count, want);
    }
    CHECK_GL(GL_NO_ERROR);
    done("aliased points");

    /* An image of all of them. */
    fresh();
    glColor4f(1, 1, 1, 1);
    for (k = 0; k < 7; ++k) {
        glPointSize(pts[k].size);
        p[0] = pts[k].x, p[1] = pts[k].y;
        draw(GL_POINTS, p, 1);
    }
    ct_save("points");
    glPointSize(1);
}

/* ---------------------------------------------------------------- smooth points, lines */

/* Sum of red / 255 over [x0, x1] x [y0, y1] of the last grab. */
static double coverage(int x0, int y0, int x1, int y1)
{
    double s = 0;
    int x, y;
    for (y = y0; y <= y1; ++y)
        for (x = x0; x <= x1; ++x)
            s += red(x, y) / 255.0;
    return s;
}

static void check_area(double got, double want, const char *what)
{
    char m[160];
    printf("%s: covered area %.2f, expected %.2f\n", what, got, want);
    ++ct.checks;
    if (!(fabs(got - want) <= 0.1 * want)) {
        snprintf(m, sizeof m, "%s: covered area %.2f, expected %.2f +-10 %%", what, got, want);
        ct_fail(__FILE__, __LINE__, m);
    }
}

static void test_smooth(void)
{
    static const GLfloat p8[2] = {40.5f, 40.5f}, p7[2] = {80.3f, 40.8f};
    static const GLfloat seg[4] = {20.5f, 80.5f, 52.5f, 80.5f};
    static const GLfloat seg_d[4] = {70.25f, 70.5f, 100.25f, 94.5f};
    GLfloat range[2], p[2];
    double area;

    begin();
    fresh();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE);
    glColor4f(1, 1, 1, 1);
    glEnable(GL_POINT_SMOOTH);
    glPointSize(8);
    draw(GL_POINTS, p8, 1);
    glPointSize(7);
    draw(GL_POINTS, p7, 1);
    glDisable(GL_POINT_SMOOTH);
    glEnable(GL_LINE_SMOOTH);
    glLineWidth(4);
    draw(GL_LINES, seg, 2);
    glLineWidth(3);
    draw(GL_LINES, seg_d, 2);
    glDisable(GL_LINE_SMOOTH);
    CHECK_GL(GL_NO_ERROR);
    grab();
    ct_save("smooth");
    check_area(coverage(30, 30, 51, 51), PI * 16, "smooth point of size 8");
    check_area(coverage(70, 30, 91, 51), PI * 12.25, "smooth point of size 7");
    check_area(coverage(10, 70, 63, 91), 4.0 * 32, "smooth line 4 x 32");
    check_area(coverage(64, 64, 106, 100), 3.0 * sqrt(30.0 * 30.0 + 24.0 * 24.0),
               "smooth slanted line of width 3");
    /* Fully covered pixels: the 2 x 2 around the size-8 point's center, the line's middle. */
    CHECK_PIXEL(40, 40, 255, 255, 255, 255, 0);
    CHECK_PIXEL(41, 41, 255, 255, 255, 255, 0);
    CHECK_PIXEL(80, 40, 255, 255, 255, 255, 0);
    CHECK_PIXEL(36, 80, 255, 255, 255, 255, 0);
    CHECK_PIXEL(36, 79, 255, 255, 255, 255, 0);
    /* Nothing far outside. */
    CHECK_PIXEL(40, 46, 0, 0, 0, 0, 0);
    CHECK_PIXEL(36, 84, 0, 0, 0, 0, 0);
    done("smooth points and lines");

    /* Sizes above the smooth maxima are clamped to them. */
    begin();
    glGetFloatv(GL_SMOOTH_POINT_SIZE_RANGE, range);
    CHECK(range[0] <= 1 && range[1] >= 1);
    fresh();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE);
    glColor4f(1, 1, 1, 1);
    glEnable(GL_POINT_SMOOTH);
    glPointSize(range[1] + 10);
    p[0] = 144, p[1] = 144;
    draw(GL_POINTS, p, 1);
    glDisable(GL_POINT_SMOOTH);
    grab();
    area = coverage(0, 0, W - 1, H - 1);
    if (range[1] < H - 8)
        check_area(area, PI * range[1] * range[1] / 4, "smooth point clamped to the max");
    glGetFloatv(GL_SMOOTH_LINE_WIDTH_RANGE, range);
    CHECK(range[0] <= 1 && range[1] >= 1);
    fresh();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE);
    glColor4f(1, 1, 1, 1);
    glEnable(GL_LINE_SMOOTH);
    glLineWidth(range[1] + 10);
    {
        GLfloat s[4] = {100, 144, 140, 144};
        draw(GL_LINES, s, 2);
    }
    glDisable(GL_LINE_SMOOTH);
    glLineWidth(1);
    grab();
    area = coverage(0, 0, W - 1, H - 1);
    if (range[1] < H - 8)
        check_area(area, range[1] * 40.0, "smooth line clamped to the max");
    CHECK_GL(GL_NO_ERROR);
    done("smooth size clamping");
}

int main(void)
{
    ct_init(W, H);
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrthof(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnableClientState(GL_VERTEX_ARRAY);
    glDisable(GL_DITHER);

    test_fill_rules();
    test_watertight();
    test_slivers();
    test_flat_shading();
    test_lines();
    test_points();
    test_smooth();
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
