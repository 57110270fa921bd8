/*
 * The per-fragment operations of ES 1.1 §4.1, each against exact expectations, with
 * flat-colored quads whose edges lie on pixel boundaries (every covered pixel is fully inside,
 * so no fill-rule or interpolation question arises):
 *
 * - alpha test: all 8 functions against a fragment alpha below, at and above the reference,
 *   and the reference clamped to [0, 1] (§4.1.4: both are compared as 8-bit fixed point, so
 *   alpha 102 equals the reference 0.4 = 102/255 exactly);
 * - stencil test: all 8 functions with a value mask, every operation (KEEP, ZERO, REPLACE,
 *   INCR and DECR with their saturation at 0 and 255, INVERT) on the fail, depth-fail and
 *   depth-pass paths, the write mask, and the reference clamped to 255. The stencil buffer
 *   cannot be read back, so each result is checked by a second pass testing EQUAL against
 *   the expected value;
 * - depth test: all 8 functions against a nearer, an equal and a farther quad (the equal one
 *   is the same quad drawn again: §A invariance gives it the same depth), and the depth mask;
 * - blending: every source factor (9, GL_SRC_ALPHA_SATURATE included) with every destination
 *   factor (8). Colors are multiples of 15 or 17 so that most products c1 c2 / 255 are whole
 *   steps; a result is required exactly when every product in it is a whole step (or it
 *   clamps to 255), else within 1 step, since §4.1.7 fixes the arithmetic only "as if in
 *   floating point" and the conversion back to 8 bits may round either way;
 * - logic op: all 16 on an RGBA8888 surface, exact bitwise, with blending off and on (§4.1.9:
 *   when the logic op is enabled, blending is bypassed);
 * - color mask per channel, scissor with draws, dithering on an RGBA8888 surface (every
 *   color is representable, so dithering cannot change it);
 * - multisample operations (§4.1.3): GL_SAMPLE_COVERAGE, GL_SAMPLE_ALPHA_TO_COVERAGE and
 *   GL_SAMPLE_ALPHA_TO_ONE have no effect when SAMPLE_BUFFERS is 0;
 * - polygon offset (§3.5.2): units of ±1 resolve coplanar quads under GL_LESS (float and fixed
 *   entry points); the factor times the slope of a slanted quad moves the visible edge by an
 *   exact number of columns (the slope is 1/72 per pixel and the boundaries fall half a column
 *   from any pixel center, far beyond depth precision); lines and points are not offset;
 * - dithering on an RGB565 surface (§4.1.8): each component of a dithered fragment is one of
 *   the two representable values nearest the incoming one; with dithering off, every pixel
 *   gets the same one of the two; 0 and 1 are exact either way.
 *
 * Colors come from glColor4ub, so every incoming component is an exact 8-bit value.
 *
 * Checks made only on our library (CHECK_MESA_DEVIATES), where Mesa softpipe departs from the
 * specification (llvmpipe passes them): softpipe compares alpha against the unclamped
 * reference, and its polygon offset slope is about 9/16 of the window-space slope.
 */
#include "common.h"

#define W 72
#define H 72
#define CELL 8
#define COLS (W / CELL)

static int failures_before;

/* Starts a group of checks; `done` names it when any of them failed. */
static void begin(void)
{
    failures_before = ct.failures;
}

static void done(const char *what)
{
    if (ct.failures > failures_before)
        fprintf(stderr, "  ^ in: %s\n", what);
}

/* A quad covering window [x0, x1) x [y0, y1) at window depth `depth` (eye z 1 - 2 depth under
 * the glOrthof(0, W, 0, H, -1, 1) projection). */
static void rect(GLfloat x0, GLfloat y0, GLfloat x1, GLfloat y1, GLfloat depth)
{
    GLfloat z = 1 - 2 * depth;
    GLfloat v[12];
    v[0] = x0, v[1] = y0, v[2] = z;
    v[3] = x1, v[4] = y0, v[5] = z;
    v[6] = x1, v[7] = y1, v[8] = z;
    v[9] = x0, v[10] = y1, v[11] = z;
    glVertexPointer(3, GL_FLOAT, 0, v);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
}

/* Cell i of the 9 x 9 grid: its inner 6 x 6 pixels, checked at (cx(i), cy(i)). */
static int cx(int i)
{
    return (i % COLS) * CELL + 4;
}

static int cy(int i)
{
    return (i / COLS) * CELL + 4;
}

static void cell(int i, GLfloat depth)
{
    GLfloat x = (GLfloat)((i % COLS) * CELL), y = (GLfloat)((i / COLS) * CELL);
    rect(x + 1, y + 1, x + CELL - 1, y + CELL - 1, depth);
}

/* Sets cell i's stencil (all 8 x 8 pixels) with a scissored clear. */
static void cell_stencil(int i, GLint value)
{
    glEnable(GL_SCISSOR_TEST);
    glScissor((i % COLS) * CELL, (i / COLS) * CELL, CELL, CELL);
    glClearStencil(value);
    glClear(GL_STENCIL_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}

static void reset_state(void)
{
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_COLOR_LOGIC_OP);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glDepthFunc(GL_LESS);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glBlendFunc(GL_ONE, GL_ZERO);
    glPolygonOffset(0, 0);
    glClearColor(0, 0, 0, 0);
    glClearDepthf(1);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

static void setup_view(void)
{
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrthof(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnableClientState(GL_VERTEX_ARRAY);
}

static const GLenum funcs[8] = {GL_NEVER, GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                                GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};

/* Does `a func b` hold (a: the incoming / reference value, b: the stored one)? */
static int compare(GLenum func, int a, int b)
{
    switch (func) {
    case GL_NEVER: return 0;
    case GL_LESS: return a < b;
    case GL_EQUAL: return a == b;
    case GL_LEQUAL: return a <= b;
    case GL_GREATER: return a > b;
    case GL_NOTEQUAL: return a != b;
    case GL_GEQUAL: return a >= b;
    default: return 1;
    }
}

/* ---------------------------------------------------------------- alpha test */

static void test_alpha(void)
{
    static const int alphas[5] = {0, 101, 102, 103, 255};
    static const struct {
        GLenum func;
        GLfloat ref;
        int alpha, pass;
    } clamped[4] = {
        /* 1.5 clamps to 1 (255): 255 >= 255 passes, 255 < 255 fails. */
        {GL_GEQUAL, 1.5f, 255, 1},
        {GL_LESS, 1.5f, 255, 0},
        /* -0.5 clamps to 0: 0 <= 0 passes, 0 > 0 fails. */
        {GL_LEQUAL, -0.5f, 0, 1},
        {GL_GREATER, -0.5f, 0, 0},
    };
    int f, a, i;

    begin();
    reset_state();
    glEnable(GL_ALPHA_TEST);
    for (f = 0; f < 8; ++f) {
        /* 0.4f x 255 = 102.0000015: the reference converts to 102. */
        glAlphaFunc(funcs[f], 0.4f);
        for (a = 0; a < 5; ++a) {
            glColor4ub(255, 255, 255, (GLubyte)alphas[a]);
            cell(f * COLS + a, 0);
        }
    }
    CHECK_GL(GL_NO_ERROR);
    for (f = 0; f < 8; ++f) {
        for (a = 0; a < 5; ++a) {
            int i_ = f * COLS + a;
            if (compare(funcs[f], alphas[a], 102))
                CHECK_PIXEL(cx(i_), cy(i_), 255, 255, 255, alphas[a], 0);
            else
                CHECK_PIXEL(cx(i_), cy(i_), 0, 0, 0, 0, 0);
        }
    }
    done("alpha test functions");
    /* Saved before the clamping cells, where softpipe differs. */
    ct_save("alpha_test");
    begin();
    for (i = 0; i < 4; ++i) {
        glAlphaFunc(clamped[i].func, clamped[i].ref);
        glColor4ub(255, 255, 255, (GLubyte)clamped[i].alpha);
        cell(8 * COLS + i, 0);
    }
    CHECK_GL(GL_NO_ERROR);
    for (i = 0; i < 4; ++i) {
        GLubyte p[4];
        int ok;
        ct_read(cx(8 * COLS + i), cy(8 * COLS + i), p);
        ok = clamped[i].pass ? p[0] == 255 : p[0] == 0;
        /* §4.1.4 clamps the reference to [0, 1]; softpipe compares against the unclamped
         * value (llvmpipe clamps). */
        CHECK_MESA_DEVIATES(ok, "softpipe compares alpha with the unclamped reference");
    }
    done("alpha test reference clamping");
    glDisable(GL_ALPHA_TEST);
}

/* ---------------------------------------------------------------- stencil */

/* Marks every cell in `cells` whose stencil equals expected[i] green (stencil untouched). */
static void verify_stencil(const int *cells, const int *expected, int n)
{
    int i;
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_BLEND);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glColor4ub(0, 255, 0, 255);
    for (i = 0; i < n; ++i) {
        glStencilFunc(GL_EQUAL, expected[i], 0xFF);
        cell(cells[i], 0);
    }
    for (i = 0; i < n; ++i)
        CHECK_PIXEL(cx(cells[i]), cy(cells[i]), 0, 255, 0, 255, 0);
}

static int stencil_op(GLenum op, int s, int ref)
{
    switch (op) {
    case GL_KEEP: return s;
    case GL_ZERO: return 0;
    case GL_REPLACE: return ref;
    case GL_INCR: return s < 255 ? s + 1 : 255;
    case GL_DECR: return s > 0 ? s - 1 : 0;
    default: return ~s & 0xFF; /* GL_INVERT */
    }
}

static void test_stencil(void)
{
    static const int stored[6] = {0x00, 0x50, 0x5A, 0x5F, 0xA5, 0xFF};
    static const GLenum ops[6] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT};
    static const int op_values[3] = {0x00, 0x5A, 0xFF};
    int cells[81], expected[81];
    int n, f, s, m, path, o, v;

    /* Functions: ref 0x5A against the stored values, with masks 0xF0 and 0xFF. Rows: the
     * stored values (two groups of rows for the two masks); columns: the functions. */
    for (m = 0; m < 2; ++m) {
        int mask = m == 0 ? 0xF0 : 0xFF;
        begin();
        reset_state();
        for (s = 0; s < 6; ++s)
            for (f = 0; f < 8; ++f)
                cell_stencil(s * COLS + f, stored[s]);
        glEnable(GL_STENCIL_TEST);
        glColor4ub(255, 255, 255, 255);
        for (f = 0; f < 8; ++f) {
            glStencilFunc(funcs[f], 0x5A, (GLuint)mask);
            for (s = 0; s < 6; ++s)
                cell(s * COLS + f, 0);
        }
        CHECK_GL(GL_NO_ERROR);
        for (s = 0; s < 6; ++s) {
            for (f = 0; f < 8; ++f) {
                int i = s * COLS + f;
                if (compare(funcs[f], 0x5A & mask, stored[s] & mask))
                    CHECK_PIXEL(cx(i), cy(i), 255, 255, 255, 255, 0);
                else
                    CHECK_PIXEL(cx(i), cy(i), 0, 0, 0, 0, 0);
            }
        }
        /* The test never writes the stencil (ops KEEP): the stored values are intact. */
        n = 0;
        for (s = 0; s < 6; ++s) {
            for (f = 0; f < 8; ++f) {
                cells[n] = s * COLS + f;
                expected[n++] = stored[s];
            }
        }
        verify_stencil(cells, expected, n);
        done(m == 0 ? "stencil functions, mask 0xF0" : "stencil functions, mask 0xFF");
        if (m == 0)
            ct_save("stencil_funcs");
    }

    /* Operations on each path. Row = path * 3 + stored value, column = operation. The two
     * other slots get an operation that would leave a different value (INVERT, or ZERO when
     * the tested one is INVERT), so a wrong slot shows. Paths: 0 stencil fails (NEVER);
     * 1 stencil passes, depth fails (depth cleared to 0); 2 both pass (depth cleared to 1). */
    begin();
    reset_state();
    n = 0;
    for (path = 0; path < 3; ++path)
        for (v = 0; v < 3; ++v)
            for (o = 0; o < 6; ++o)
                cell_stencil((path * 3 + v) * COLS + o, op_values[v]);
    glEnable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    for (path = 0; path < 3; ++path) {
        glClearDepthf(path == 1 ? 0.0f : 1.0f);
        glClear(GL_DEPTH_BUFFER_BIT);
        glStencilFunc(path == 0 ? GL_NEVER : GL_ALWAYS, 0x3C, 0xFF);
        for (o = 0; o < 6; ++o) {
            GLenum other = ops[o] == GL_INVERT ? GL_ZERO : GL_INVERT;
            glStencilOp(path == 0 ? ops[o] : other, path == 1 ? ops[o] : other,
                        path == 2 ? ops[o] : other);
            for (v = 0; v < 3; ++v) {
                cells[n] = (path * 3 + v) * COLS + o;
                expected[n++] = stencil_op(ops[o], op_values[v], 0x3C);
                cell((path * 3 + v) * COLS + o, 0.5f);
            }
        }
    }
    /* Column 6: the write mask 0xF0 (REPLACE 0x3C over 0x5A keeps the low nibble: 0x3A;
     * INVERT: 0xAA; ZERO: 0x0A), 0x0F (DECR 0x50 -> 0x4F, masked: 0x5F; INCR saturates 0xFF).
     * Column 7: the reference clamps to 2^8 - 1 (REPLACE with ref 300 writes 255). */
    {
        static const struct {
            GLenum op;
            GLuint mask;
            int ref, before, after;
        } masked[6] = {
            {GL_REPLACE, 0xF0, 0x3C, 0x5A, 0x3A}, {GL_INVERT, 0xF0, 0, 0x5A, 0xAA},
            {GL_ZERO, 0xF0, 0, 0x5A, 0x0A},       {GL_DECR, 0x0F, 0, 0x50, 0x5F},
            {GL_INCR, 0x0F, 0, 0xFF, 0xFF},       {GL_INCR, 0x00, 0, 0x12, 0x12},
        };
        int k;
        glDisable(GL_DEPTH_TEST);
        for (k = 0; k < 6; ++k) {
            int i = k * COLS + 6;
            glStencilMask(0xFF);
            cell_stencil(i, masked[k].before);
            glStencilMask(masked[k].mask);
            glStencilFunc(GL_ALWAYS, masked[k].ref, 0xFF);
            glStencilOp(GL_KEEP, GL_KEEP, masked[k].op);
            cell(i, 0);
            cells[n] = i;
            expected[n++] = masked[k].after;
        }
        glStencilMask(0xFF);
        cell_stencil(7, 0x00);
        glStencilFunc(GL_ALWAYS, 300, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        cell(7, 0);
        CHECK_GL(GL_NO_ERROR);
    }
    verify_stencil(cells, expected, n);
    done("stencil operations and write mask");
    /* §4.1.5: ref is clamped to [0, 2^s - 1]. */
    begin();
    glClear(GL_COLOR_BUFFER_BIT);
    glStencilFunc(GL_EQUAL, 0xFF, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glColor4ub(0, 255, 0, 255);
    cell(7, 0);
    {
        GLubyte p[4];
        ct_read(cx(7), cy(7), p);
        CHECK(p[1] == 255);
    }
    done("stencil reference clamping");
    /* An image of the operations, each cell green where its stencil is as expected. */
    verify_stencil(cells, expected, n);
    ct_save("stencil_ops");
}

/* ---------------------------------------------------------------- depth */

static void test_depth(void)
{
    static const GLfloat depths[3] = {0.25f, 0.5f, 0.75f};
    int f, d;

    begin();
    reset_state();
    glEnable(GL_DEPTH_TEST);
    for (f = 0; f < 8; ++f) {
        for (d = 0; d < 3; ++d) {
            int i = f * COLS + d;
            /* The stored depth: this very quad at 0.5, drawn with ALWAYS. */
            glDepthFunc(GL_ALWAYS);
            glColor4ub(0, 0, 255, 255);
            cell(i, 0.5f);
            glDepthFunc(funcs[f]);
            glColor4ub(255, 255, 0, 255);
            cell(i, depths[d]);
        }
    }
    CHECK_GL(GL_NO_ERROR);
    for (f = 0; f < 8; ++f) {
        for (d = 0; d < 3; ++d) {
            int i = f * COLS + d;
            /* Window depth compared: incoming (d: 1, 2, 3 quarters) func stored (2). */
            if (compare(funcs[f], d + 1, 2))
                CHECK_PIXEL(cx(i), cy(i), 255, 255, 0, 255, 0);
            else
                CHECK_PIXEL(cx(i), cy(i), 0, 0, 255, 255, 0);
        }
    }
    done("depth functions");
    ct_save("depth_funcs");

    /* Depth mask: with writes off, a nearer quad passes LESS but leaves 0.5 stored, so the
     * 0.5 quad passes EQUAL afterwards; with writes on it does not. */
    begin();
    reset_state();
    glEnable(GL_DEPTH_TEST);
    for (d = 0; d < 2; ++d) {
        int i = 4 + d;
        glDepthFunc(GL_ALWAYS);
        glColor4ub(0, 0, 255, 255);
        cell(i, 0.5f);
        glDepthMask(d == 0 ? GL_FALSE : GL_TRUE);
        glDepthFunc(GL_LESS);
        glColor4ub(255, 255, 0, 255);
        cell(i, 0.25f);
        CHECK_PIXEL(cx(i), cy(i), 255, 255, 0, 255, 0);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_EQUAL);
        glColor4ub(255, 0, 255, 255);
        cell(i, 0.5f);
    }
    CHECK_PIXEL(cx(4), cy(4), 255, 0, 255, 255, 0);
    CHECK_PIXEL(cx(5), cy(5), 255, 255, 0, 255, 0);
    /* The depth test disabled: no test and no depth writes (§4.1.6). */
    glDisable(GL_DEPTH_TEST);
    glColor4ub(0, 255, 255, 255);
    cell(6, 0.75f);
    CHECK_PIXEL(cx(6), cy(6), 0, 255, 255, 255, 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glColor4ub(255, 255, 255, 255);
    cell(6, 0.9f); /* stored depth is still the cleared 1.0 */
    CHECK_PIXEL(cx(6), cy(6), 255, 255, 255, 255, 0);
    done("depth mask");
}

/* ---------------------------------------------------------------- blending */

/* A factor as a multiple of 1/255 for channel c (3 = alpha). */
static int factor(GLenum f, int c, const int s[4], const int d[4])
{
    switch (f) {
    case GL_ZERO: return 0;
    case GL_ONE: return 255;
    case GL_SRC_COLOR: return s[c];
    case GL_ONE_MINUS_SRC_COLOR: return 255 - s[c];
    case GL_DST_COLOR: return d[c];
    case GL_ONE_MINUS_DST_COLOR: return 255 - d[c];
    case GL_SRC_ALPHA: return s[3];
    case GL_ONE_MINUS_SRC_ALPHA: return 255 - s[3];
    case GL_DST_ALPHA: return d[3];
    case GL_ONE_MINUS_DST_ALPHA: return 255 - d[3];
    default: /* GL_SRC_ALPHA_SATURATE: (f, f, f, 1), f = min(As, 1 - Ad) */
        if (c == 3)
            return 255;
        return s[3] < 255 - d[3] ? s[3] : 255 - d[3];
    }
}

static void test_blend(void)
{
    static const GLenum src[9] = {GL_ZERO,
                                  GL_ONE,
                                  GL_DST_COLOR,
                                  GL_ONE_MINUS_DST_COLOR,
                                  GL_SRC_ALPHA,
                                  GL_ONE_MINUS_SRC_ALPHA,
                                  GL_DST_ALPHA,
                                  GL_ONE_MINUS_DST_ALPHA,
                                  GL_SRC_ALPHA_SATURATE};
    static const GLenum dst[8] = {GL_ZERO,         GL_ONE,         GL_SRC_COLOR,
                                  GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA,
                                  GL_DST_ALPHA,    GL_ONE_MINUS_DST_ALPHA};
    /* Source colors are multiples of 15, destination colors multiples of 17 (products of the
     * two are whole steps); alpha 153 = 9 x 17 and 170 = 10 x 17 (saturate: min(153, 85)). */
    static const int s[4] = {60, 195, 30, 153};
    static const int d[4] = {85, 170, 34, 170};
    int a, b, c, exact = 0, total = 0;

    begin();
    reset_state();
    for (a = 0; a < 9; ++a) {
        for (b = 0; b < 8; ++b) {
            int i = a * COLS + b;
            glDisable(GL_BLEND);
            glColor4ub((GLubyte)d[0], (GLubyte)d[1], (GLubyte)d[2], (GLubyte)d[3]);
            cell(i, 0);
            glEnable(GL_BLEND);
            glBlendFunc(src[a], dst[b]);
            glColor4ub((GLubyte)s[0], (GLubyte)s[1], (GLubyte)s[2], (GLubyte)s[3]);
            cell(i, 0);
        }
    }
    CHECK_GL(GL_NO_ERROR);
    for (a = 0; a < 9; ++a) {
        for (b = 0; b < 8; ++b) {
            int i = a * COLS + b;
            GLubyte p[4];
            ct_read(cx(i), cy(i), p);
            for (c = 0; c < 4; ++c) {
                int ps = s[c] * factor(src[a], c, s, d);
                int pd = d[c] * factor(dst[b], c, s, d);
                double sum = (ps + pd) / 255.0; /* in 8-bit steps */
                int want = sum >= 255 ? 255 : (int)(sum + 0.5);
                int tol = (ps % 255 == 0 && pd % 255 == 0) || sum >= 256 ? 0 : 1;
                exact += tol == 0;
                ++total;
                ++ct.checks;
                if (!ct_near(p[c], want, tol)) {
                    char m[160];
                    snprintf(m, sizeof m,
                             "blend src #%d dst #%d channel %d: %d, expected %d +-%d", a, b, c,
                             p[c], want, tol);
                    ct_fail(__FILE__, __LINE__, m);
                }
            }
        }
    }
    printf("blending: %d of %d channel results required exactly\n", exact, total);
    done("blend factors");
    ct_save("blend");
    glDisable(GL_BLEND);
}

/* ---------------------------------------------------------------- logic op */

static int logic(GLenum op, int s, int d)
{
    int r;
    switch (op) {
    case GL_CLEAR: r = 0; break;
    case GL_AND: r = s & d; break;
    case GL_AND_REVERSE: r = s & ~d; break;
    case GL_COPY: r = s; break;
    case GL_AND_INVERTED: r = ~s & d; break;
    case GL_NOOP: r = d; break;
    case GL_XOR: r = s ^ d; break;
    case GL_OR: r = s | d; break;
    case GL_NOR: r = ~(s | d); break;
    case GL_EQUIV: r = ~(s ^ d); break;
    case GL_INVERT: r = ~d; break;
    case GL_OR_REVERSE: r = s | ~d; break;
    case GL_COPY_INVERTED: r = ~s; break;
    case GL_OR_INVERTED: r = ~s | d; break;
    case GL_NAND: r = ~(s & d); break;
    default: r = ~0; break; /* GL_SET */
    }
    return r & 0xFF;
}

static void test_logic_op(void)
{
    static const int s[4] = {0xCC, 0x0F, 0xF0, 0x5A};
    static const int d[4] = {0xAA, 0x33, 0x3C, 0xC3};
    int op, blend;

    begin();
    reset_state();
    for (blend = 0; blend < 2; ++blend) {
        for (op = 0; op < 16; ++op) {
            int i = blend * 2 * COLS + (op / 8) * COLS + op % 8;
            glDisable(GL_COLOR_LOGIC_OP);
            glDisable(GL_BLEND);
            glColor4ub((GLubyte)d[0], (GLubyte)d[1], (GLubyte)d[2], (GLubyte)d[3]);
            cell(i, 0);
            glEnable(GL_COLOR_LOGIC_OP);
            glLogicOp((GLenum)(GL_CLEAR + op));
            if (blend) {
                /* ONE, ONE would saturate most channels: the logic op must win. */
                glEnable(GL_BLEND);
                glBlendFunc(GL_ONE, GL_ONE);
            }
            glColor4ub((GLubyte)s[0], (GLubyte)s[1], (GLubyte)s[2], (GLubyte)s[3]);
            cell(i, 0);
        }
    }
    CHECK_GL(GL_NO_ERROR);
    for (blend = 0; blend < 2; ++blend) {
        for (op = 0; op < 16; ++op) {
            GLenum e = (GLenum)(GL_CLEAR + op);
            int i = blend * 2 * COLS + (op / 8) * COLS + op % 8;
            CHECK_PIXEL(cx(i), cy(i), logic(e, s[0], d[0]), logic(e, s[1], d[1]),
                        logic(e, s[2], d[2]), logic(e, s[3], d[3]), 0);
        }
    }
    done("logic ops");
    ct_save("logic_op");
    glDisable(GL_COLOR_LOGIC_OP);
    glDisable(GL_BLEND);
}

/* ---------------------------------------------------------------- masks, scissor, dither */

static void test_color_mask_scissor_dither(void)
{
    static const GLboolean masks[6][4] = {
        {GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE}, {GL_FALSE, GL_TRUE, GL_FALSE, GL_FALSE},
        {GL_FALSE, GL_FALSE, GL_TRUE, GL_FALSE}, {GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE},
        {GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE}, {GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE},
    };
    static const int bg[4] = {0x11, 0x22, 0x33, 0x44}, fg[4] = {0xEE, 0xDD, 0xCC, 0xBB};
    int k, c, dith, i;

    begin();
    reset_state();
    glClearColor(0x11 / 255.0f, 0x22 / 255.0f, 0x33 / 255.0f, 0x44 / 255.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4ub(0xEE, 0xDD, 0xCC, 0xBB);
    for (k = 0; k < 6; ++k) {
        glColorMask(masks[k][0], masks[k][1], masks[k][2], masks[k][3]);
        cell(k, 0);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    for (k = 0; k < 6; ++k) {
        int want[4];
        for (c = 0; c < 4; ++c)
            want[c] = masks[k][c] ? fg[c] : bg[c];
        CHECK_PIXEL(cx(k), cy(k), want[0], want[1], want[2], want[3], 0);
    }
    done("color mask");

    /* Scissor: a quad over the whole surface lands only in [10, 30) x [12, 28). */
    begin();
    glEnable(GL_SCISSOR_TEST);
    glScissor(10, 20, 20, 16);
    glColor4ub(255, 0, 0, 255);
    rect(0, 0, W, H, 0);
    glDisable(GL_SCISSOR_TEST);
    CHECK_PIXEL(10, 20, 255, 0, 0, 255, 0);
    CHECK_PIXEL(29, 35, 255, 0, 0, 255, 0);
    CHECK_PIXEL(9, 20, 0x11, 0x22, 0x33, 0x44, 0);
    CHECK_PIXEL(10, 19, 0x11, 0x22, 0x33, 0x44, 0);
    CHECK_PIXEL(30, 35, 0x11, 0x22, 0x33, 0x44, 0);
    CHECK_PIXEL(29, 36, 0x11, 0x22, 0x33, 0x44, 0);
    /* A scissor box partly outside the surface and one of zero width. */
    glEnable(GL_SCISSOR_TEST);
    glScissor(W - 4, -10, 100, 14);
    glColor4ub(0, 0, 255, 255);
    rect(0, 0, W, H, 0);
    glScissor(40, 40, 0, 10);
    rect(0, 0, W, H, 0);
    glDisable(GL_SCISSOR_TEST);
    CHECK_PIXEL(W - 4, 0, 0, 0, 255, 255, 0);
    CHECK_PIXEL(W - 1, 3, 0, 0, 255, 255, 0);
    CHECK_PIXEL(W - 5, 0, 0x11, 0x22, 0x33, 0x44, 0);
    CHECK_PIXEL(W - 1, 4, 0x11, 0x22, 0x33, 0x44, 0);
    CHECK_PIXEL(40, 40, 0x11, 0x22, 0x33, 0x44, 0);
    CHECK_GL(GL_NO_ERROR);
    done("scissor");
    ct_save("mask_scissor");

    /* Dithering on RGBA8888: every incoming component is exactly representable, so both
     * values dithering may choose between are that value (§4.1.8). A ramp of 81 colors. */
    begin();
    CHECK(glIsEnabled(GL_DITHER)); /* initially enabled */
    for (dith = 0; dith < 2; ++dith) {
        if (dith)
            glEnable(GL_DITHER);
        else
            glDisable(GL_DITHER);
        glClear(GL_COLOR_BUFFER_BIT);
        for (i = 0; i < COLS * COLS; ++i) {
            GLfloat x = (GLfloat)((i % COLS) * CELL), y = (GLfloat)((i / COLS) * CELL);
            glColor4ub((GLubyte)(i * 3), (GLubyte)(255 - i * 3), (GLubyte)(i * 7 % 256),
                       (GLubyte)(i * 11 % 256));
            rect(x, y, x + CELL, y + CELL, 0);
        }
        for (i = 0; i < COLS * COLS; i += 4) {
            CHECK_PIXEL(cx(i), cy(i), i * 3, 255 - i * 3, i * 7 % 256, i * 11 % 256, 0);
            CHECK_PIXEL(cx(i) - 3, cy(i) + 3, i * 3, 255 - i * 3, i * 7 % 256, i * 11 % 256, 0);
        }
    }
    done("dither on RGBA8888");
    ct_save("dither_8888");
}

/* ---------------------------------------------------------------- multisample ops */

static void test_multisample_ops(void)
{
    GLint sample_buffers = -1;

    begin();
    reset_state();
    /* Both are in ES 1.1's state tables (§6.2), 0 on every config here. */
    glGetIntegerv(GL_SAMPLE_BUFFERS, &sample_buffers);
    CHECK_GL(GL_NO_ERROR);
    CHECK(sample_buffers == 0);
    sample_buffers = -1;
    glGetIntegerv(GL_SAMPLES, &sample_buffers);
    CHECK_GL(GL_NO_ERROR);
    CHECK(sample_buffers == 0);
    CHECK(glIsEnabled(GL_MULTISAMPLE));
    /* Coverage 0 would discard every sample if the step ran. */
    glEnable(GL_SAMPLE_COVERAGE);
    glSampleCoverage(0, GL_FALSE);
    glColor4ub(255, 0, 0, 255);
    cell(0, 0);
    glSampleCoverage(1, GL_TRUE);
    cell(1, 0);
    glDisable(GL_SAMPLE_COVERAGE);
    /* Alpha 0 would give coverage 0. */
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glColor4ub(0, 255, 0, 0);
    cell(2, 0);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    /* Alpha would become 1. */
    glEnable(GL_SAMPLE_ALPHA_TO_ONE);
    glColor4ub(0, 0, 255, 102);
    cell(3, 0);
    /* All three at once, GL_MULTISAMPLE off and on. */
    glEnable(GL_SAMPLE_COVERAGE);
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glSampleCoverage(0, GL_FALSE);
    glColor4ub(255, 255, 0, 51);
    cell(4, 0);
    glDisable(GL_MULTISAMPLE);
    cell(5, 0);
    glEnable(GL_MULTISAMPLE);
    glDisable(GL_SAMPLE_COVERAGE);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glDisable(GL_SAMPLE_ALPHA_TO_ONE);
    glSampleCoverage(1, GL_FALSE);
    CHECK_GL(GL_NO_ERROR);
    CHECK_PIXEL(cx(0), cy(0), 255, 0, 0, 255, 0);
    CHECK_PIXEL(cx(1), cy(1), 255, 0, 0, 255, 0);
    CHECK_PIXEL(cx(2), cy(2), 0, 255, 0, 0, 0);
    CHECK_PIXEL(cx(3), cy(3), 0, 0, 255, 102, 0);
    CHECK_PIXEL(cx(4), cy(4), 255, 255, 0, 51, 0);
    CHECK_PIXEL(cx(5), cy(5), 255, 255, 0, 51, 0);
    done("multisample operations on a single-sample surface");
}

/* ---------------------------------------------------------------- polygon offset */

/* A quad over columns [0, W) whose window depth rises from 0 at x = 0 to 1 at x = W. */
static void slanted(GLfloat y0, GLfloat y1)
{
    GLfloat v[12];
    v[0] = 0, v[1] = y0, v[2] = 1;
    v[3] = W, v[4] = y0, v[5] = -1;
    v[6] = W, v[7] = y1, v[8] = -1;
    v[9] = 0, v[10] = y1, v[11] = 1;
    glVertexPointer(3, GL_FLOAT, 0, v);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
}

static void test_polygon_offset(void)
{
    static const GLfloat factors[3] = {0, -8, 8};
    static const int last_pass[3] = {35, 43, 27};
    GLfloat line[6] = {4, 61.5f, 0, 40, 61.5f, 0};
    GLfloat point[3] = {50.5f, 61.5f, 0};
    int k;

    begin();
    reset_state();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    /* Row 0: coplanar pairs at depth 0.5, the second quad yellow. */
    for (k = 0; k < 5; ++k) {
        glDisable(GL_POLYGON_OFFSET_FILL);
        glColor4ub(0, 0, 255, 255);
        if (k == 3) {
            /* The first quad pushed back by one unit: the plain second one is in front. */
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(0, 1);
        }
        cell(k, 0.5f);
        glDisable(GL_POLYGON_OFFSET_FILL);
        glColor4ub(255, 255, 0, 255);
        switch (k) {
        case 0: /* no offset: equal depths fail LESS */
            break;
        case 1: /* units -1: one resolvable step nearer */
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(0, -1);
            break;
        case 2: /* the same through the fixed-point entry point */
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffsetx(0, -0x10000);
            break;
        case 3:
            break;
        default: /* units +1: farther, fails */
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffsetx(0, 0x10000);
            break;
        }
        cell(k, 0.5f);
    }
    CHECK_GL(GL_NO_ERROR);
    CHECK_PIXEL(cx(0), cy(0), 0, 0, 255, 255, 0);
    CHECK_PIXEL(cx(1), cy(1), 255, 255, 0, 255, 0);
    CHECK_PIXEL(cx(2), cy(2), 255, 255, 0, 255, 0);
    CHECK_PIXEL(cx(3), cy(3), 255, 255, 0, 255, 0);
    CHECK_PIXEL(cx(4), cy(4), 0, 0, 255, 255, 0);
    done("polygon offset units on coplanar quads");

    /* Slanted quads over a flat one at depth 0.5: the depth at column x is (x + 0.5) / 72,
     * the slope m = 1/72 in x and 0 in y (so the exact and the max-approximated m agree), and
     * the offset o = factor / 72. Passes LESS where x + 0.5 + factor < 36. */
    begin();
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColor4ub(0, 0, 255, 255);
    rect(0, 16, W, 40, 0.5f);
    glColor4ub(255, 255, 0, 255);
    glEnable(GL_POLYGON_OFFSET_FILL);
    for (k = 0; k < 3; ++k) {
        glPolygonOffset(factors[k], 0);
        slanted(16 + 8 * (GLfloat)k, 20 + 8 * (GLfloat)k);
    }
    for (k = 0; k < 3; ++k) {
        int y = 18 + 8 * k;
        CHECK_PIXEL(0, y, 255, 255, 0, 255, 0);
        if (k == 0) {
            CHECK_PIXEL(last_pass[k], y, 255, 255, 0, 255, 0);
            CHECK_PIXEL(last_pass[k] + 1, y, 0, 0, 255, 255, 0);
        } else {
            /* softpipe's slope m is 9/16 of the window-space one (its edges land at columns
             * 40 and 31), where §3.5.2 defines m from window z over window x and y;
             * llvmpipe agrees with the specification. */
            GLubyte p[4], q[4];
            ct_read(last_pass[k], y, p);
            ct_read(last_pass[k] + 1, y, q);
            CHECK_MESA_DEVIATES(p[0] == 255 && p[2] == 0 && q[0] == 0 && q[2] == 255,
                                "softpipe scales the polygon offset slope by about 9/16");
        }
        CHECK_PIXEL(W - 1, y, 0, 0, 255, 255, 0);
    }
    done("polygon offset factor on a slanted quad");

    /* Lines and points are not offset (ES 1.1 has only POLYGON_OFFSET_FILL): over a quad at
     * depth 0.5, a triangle pair, a line and a point at 0.49 with 10^6 units (>= 0.06 at 24
     * bits) of offset: the quad is pushed behind and fails, the line and point pass. */
    begin();
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColor4ub(0, 0, 255, 255);
    rect(0, 48, W, H, 0.5f);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(0, 1e6f);
    glColor4ub(255, 255, 0, 255);
    rect(4, 50, 40, 56, 0.49f);
    line[2] = line[5] = point[2] = 1 - 2 * 0.49f;
    glVertexPointer(3, GL_FLOAT, 0, line);
    glDrawArrays(GL_LINES, 0, 2);
    glVertexPointer(3, GL_FLOAT, 0, point);
    glDrawArrays(GL_POINTS, 0, 1);
    glDisable(GL_POLYGON_OFFSET_FILL);
    CHECK_GL(GL_NO_ERROR);
    CHECK_PIXEL(20, 52, 0, 0, 255, 255, 0);
    CHECK_PIXEL(20, 61, 255, 255, 0, 255, 0);
    CHECK_PIXEL(50, 61, 255, 255, 0, 255, 0);
    done("polygon offset leaves lines and points");
    ct_save("polygon_offset");
}

/* ---------------------------------------------------------------- RGB565 dithering */

/* The 8-bit reading of n-bit value v (§4.3.1: v / (2^n - 1), scaled to 255 and rounded). */
static int expand(int v, int bits)
{
    int max = (1 << bits) - 1;
    return (v * 255 + max / 2) / max;
}

static void test_dither_565(void)
{
    static const EGLint rgb565[] = {EGL_RED_SIZE, 5, EGL_GREEN_SIZE, 6, EGL_BLUE_SIZE, 5,
                                    EGL_ALPHA_SIZE, 0, EGL_BUFFER_SIZE, 16, EGL_NONE};
    /* 0.3 x 31 = 9.3, 0.3 x 63 = 18.9; 0.7 x 31 = 21.7; 0.45 x 63 = 28.35. */
    static const GLfloat color[3] = {0.3f, 0.3f, 0.7f};
    static const GLfloat color2[3] = {0.7f, 0.45f, 0.3f};
    static GLubyte pixels[W * H * 4];
    int dith, k, x, y, c, bits[3] = {5, 6, 5};

    eglMakeCurrent(ct.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(ct.display, ct.context);
    eglDestroySurface(ct.display, ct.surface);
    ct_init_config(W, H, rgb565);
    setup_view();
    begin();
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    /* Representable colors (0 and 1 are the only ones a float gives exactly) stay exact. */
    glEnable(GL_DITHER);
    glColor4f(1, 0, 1, 1);
    rect(0, 0, W, 8, 0);
    glColor4f(0, 1, 0, 1);
    rect(0, 8, W, 16, 0);
    for (x = 0; x < W; x += 5) {
        CHECK_PIXEL(x, 3, 255, 0, 255, 255, 0);
        CHECK_PIXEL(x, 12, 0, 255, 0, 255, 0);
    }
    ct_save("exact_565");
    done("representable colors on RGB565");

    for (dith = 0; dith < 2; ++dith) {
        begin();
        if (dith)
            glEnable(GL_DITHER);
        else
            glDisable(GL_DITHER);
        glColor4f(color[0], color[1], color[2], 1);
        rect(0, 16, W, 44, 0);
        glColor4f(color2[0], color2[1], color2[2], 1);
        rect(0, 44, W, H, 0);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
        for (k = 0; k < 2; ++k) {
            const GLfloat *col = k == 0 ? color : color2;
            int first[3] = {-1, -1, -1}, uniform = 1, member = 1;
            for (y = k == 0 ? 16 : 44; y < (k == 0 ? 44 : H); ++y) {
                for (x = 0; x < W; ++x) {
                    const GLubyte *p = pixels + 4 * (y * W + x);
                    for (c = 0; c < 3; ++c) {
                        int max = (1 << bits[c]) - 1;
                        int lo = (int)(col[c] * (GLfloat)max); /* floor: all positive */
                        if (p[c] != expand(lo, bits[c]) && p[c] != expand(lo + 1, bits[c]))
                            member = 0;
                        if (first[c] < 0)
                            first[c] = p[c];
                        else if (first[c] != p[c])
                            uniform = 0;
                    }
                }
            }
            /* Dithered or not, only the two nearest values (§4.1.8). */
            CHECK(member);
            /* Without dithering the choice may not depend on x and y. */
            if (!dith)
                CHECK(uniform);
        }
        done(dith ? "dithering on RGB565" : "no dithering on RGB565");
    }
}

int main(void)
{
    ct_init(W, H);
    setup_view();
    test_alpha();
    test_stencil();
    test_depth();
    test_blend();
    test_logic_op();
    test_color_mask_scissor_dither();
    test_multisample_ops();
    test_polygon_offset();
    CHECK_GL(GL_NO_ERROR);
    test_dither_565();
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
