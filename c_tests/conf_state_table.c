/*
 * conf_state_table: the OpenGL ES 1.1 state tables (specification chapter 6, tables 6.3 to
 * 6.22, plus the OES extensions this library lists), walked from one table.
 *
 * Every entry is queried through glGetBooleanv, glGetIntegerv, glGetFloatv and glGetFixedv.
 * Each answer must raise no error, write exactly `count` values (guard words after them stay
 * untouched), agree with the others under the conversions of ES 1.1 section 6.1.2, and equal
 * the initial value the state tables give. Per-light, material, texture environment, texture
 * object, clip plane, pointer and enable state is walked through its type-specific getters
 * (glGetLight*, glGetMaterial*, glGetTexEnv*, glGetTexParameter*, glGetClipPlane*,
 * glGetPointerv, glIsEnabled) in the same way. Prints the number of state variables checked.
 */
#include "common.h"

#include <limits.h>
#include <math.h>

#define W 48
#define H 40
#define GUARD 20 /* a matrix is the largest value; GUARD - 16 words stay untouched */

enum kind {
    K_ENUM,  /* integers and enums: every getter gives the exact value */
    K_BOOL,  /* booleans */
    K_FLOAT, /* floats: integer queries round to nearest */
    K_NORM,  /* colors, normals, depth values: integer queries map [-1, 1] onto the ints */
    K_MIN,   /* implementation-dependent, at least init[0] (per component) */
    K_RANGE, /* implementation-dependent [min, max] range that contains init[0] */
    K_MASK,  /* an all-ones bit mask: the low 8 bits (the stencil bits) are set */
    K_BITS,  /* OES_matrix_get: only glGetIntegerv, IEEE-754 bits of the float matrix */
    K_EXACT, /* implementation value known for the chosen config */
};

struct entry {
    GLenum pname;
    const char *name;
    enum kind kind;
    int count;
    float init[16];
    const char *ext; /* checked only when GL_EXTENSIONS lists it (NULL: core) */
};

#define E(p, k, n, ...) {p, #p, k, n, {__VA_ARGS__}, NULL}
#define X(ext, p, k, n, ...) {p, #p, k, n, {__VA_ARGS__}, ext}
#define IDENT 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1

/* The per-texture-unit entries (walked once per unit, with that unit active). */
static const struct entry unit_table[] = {
    E(GL_TEXTURE_2D, K_BOOL, 1, 0),
    E(GL_TEXTURE_BINDING_2D, K_ENUM, 1, 0),
    E(GL_CURRENT_TEXTURE_COORDS, K_FLOAT, 4, 0, 0, 0, 1),
    E(GL_TEXTURE_MATRIX, K_FLOAT, 16, IDENT),
    E(GL_TEXTURE_STACK_DEPTH, K_ENUM, 1, 1),
    X("GL_OES_matrix_get", GL_TEXTURE_MATRIX_FLOAT_AS_INT_BITS_OES, K_BITS, 16, IDENT),
    /* client active unit */
    E(GL_TEXTURE_COORD_ARRAY, K_BOOL, 1, 0),
    E(GL_TEXTURE_COORD_ARRAY_SIZE, K_ENUM, 1, 4),
    E(GL_TEXTURE_COORD_ARRAY_TYPE, K_ENUM, 1, GL_FLOAT),
    E(GL_TEXTURE_COORD_ARRAY_STRIDE, K_ENUM, 1, 0),
    E(GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, K_ENUM, 1, 0),
};

static const struct entry table[] = {
    /* 6.3 current values */
    E(GL_CURRENT_COLOR, K_NORM, 4, 1, 1, 1, 1),
    E(GL_CURRENT_NORMAL, K_NORM, 3, 0, 0, 1),
    /* 6.4 vertex arrays */
    E(GL_CLIENT_ACTIVE_TEXTURE, K_ENUM, 1, GL_TEXTURE0),
    E(GL_VERTEX_ARRAY, K_BOOL, 1, 0),
    E(GL_VERTEX_ARRAY_SIZE, K_ENUM, 1, 4),
    E(GL_VERTEX_ARRAY_STRIDE, K_ENUM, 1, 0),
    E(GL_VERTEX_ARRAY_TYPE, K_ENUM, 1, GL_FLOAT),
    E(GL_NORMAL_ARRAY, K_BOOL, 1, 0),
    E(GL_NORMAL_ARRAY_STRIDE, K_ENUM, 1, 0),
    E(GL_NORMAL_ARRAY_TYPE, K_ENUM, 1, GL_FLOAT),
    E(GL_COLOR_ARRAY, K_BOOL, 1, 0),
    E(GL_COLOR_ARRAY_SIZE, K_ENUM, 1, 4),
    E(GL_COLOR_ARRAY_STRIDE, K_ENUM, 1, 0),
    E(GL_COLOR_ARRAY_TYPE, K_ENUM, 1, GL_FLOAT),
    X("GL_OES_point_size_array", GL_POINT_SIZE_ARRAY_OES, K_BOOL, 1, 0),
    X("GL_OES_point_size_array", GL_POINT_SIZE_ARRAY_STRIDE_OES, K_ENUM, 1, 0),
    X("GL_OES_point_size_array", GL_POINT_SIZE_ARRAY_TYPE_OES, K_ENUM, 1, GL_FLOAT),
    /* 6.5 buffer object bindings */
    E(GL_ARRAY_BUFFER_BINDING, K_ENUM, 1, 0),
    E(GL_ELEMENT_ARRAY_BUFFER_BINDING, K_ENUM, 1, 0),
    E(GL_VERTEX_ARRAY_BUFFER_BINDING, K_ENUM, 1, 0),
    E(GL_NORMAL_ARRAY_BUFFER_BINDING, K_ENUM, 1, 0),
    E(GL_COLOR_ARRAY_BUFFER_BINDING, K_ENUM, 1, 0),
    X("GL_OES_point_size_array", GL_POINT_SIZE_ARRAY_BUFFER_BINDING_OES, K_ENUM, 1, 0),
    /* 6.6 transformation */
    E(GL_MODELVIEW_MATRIX, K_FLOAT, 16, IDENT),
    E(GL_PROJECTION_MATRIX, K_FLOAT, 16, IDENT),
    E(GL_VIEWPORT, K_ENUM, 4, 0, 0, W, H),
    E(GL_DEPTH_RANGE, K_NORM, 2, 0, 1),
    E(GL_MODELVIEW_STACK_DEPTH, K_ENUM, 1, 1),
    E(GL_PROJECTION_STACK_DEPTH, K_ENUM, 1, 1),
    E(GL_MATRIX_MODE, K_ENUM, 1, GL_MODELVIEW),
    E(GL_NORMALIZE, K_BOOL, 1, 0),
    E(GL_RESCALE_NORMAL, K_BOOL, 1, 0),
    E(GL_CLIP_PLANE0, K_BOOL, 1, 0),
    X("GL_OES_matrix_get", GL_MODELVIEW_MATRIX_FLOAT_AS_INT_BITS_OES, K_BITS, 16, IDENT),
    X("GL_OES_matrix_get", GL_PROJECTION_MATRIX_FLOAT_AS_INT_BITS_OES, K_BITS, 16, IDENT),
    /* 6.7 coloring */
    E(GL_FOG_COLOR, K_NORM, 4, 0, 0, 0, 0),
    E(GL_FOG_DENSITY, K_FLOAT, 1, 1),
    E(GL_FOG_START, K_FLOAT, 1, 0),
    E(GL_FOG_END, K_FLOAT, 1, 1),
    E(GL_FOG_MODE, K_ENUM, 1, GL_EXP),
    E(GL_FOG, K_BOOL, 1, 0),
    E(GL_SHADE_MODEL, K_ENUM, 1, GL_SMOOTH),
    /* 6.8 lighting */
    E(GL_LIGHTING, K_BOOL, 1, 0),
    E(GL_COLOR_MATERIAL, K_BOOL, 1, 0),
    E(GL_LIGHT_MODEL_AMBIENT, K_NORM, 4, 0.2f, 0.2f, 0.2f, 1),
    E(GL_LIGHT_MODEL_TWO_SIDE, K_BOOL, 1, 0),
    E(GL_LIGHT0, K_BOOL, 1, 0),
    E(GL_LIGHT7, K_BOOL, 1, 0),
    /* 6.10 rasterization */
    E(GL_POINT_SIZE, K_FLOAT, 1, 1),
    E(GL_POINT_SMOOTH, K_BOOL, 1, 0),
    X("GL_OES_point_sprite", GL_POINT_SPRITE_OES, K_BOOL, 1, 0),
    E(GL_POINT_SIZE_MIN, K_FLOAT, 1, 0),
    /* POINT_SIZE_MAX starts at the largest supported size (checked below). */
    E(GL_POINT_FADE_THRESHOLD_SIZE, K_FLOAT, 1, 1),
    E(GL_POINT_DISTANCE_ATTENUATION, K_FLOAT, 3, 1, 0, 0),
    E(GL_LINE_WIDTH, K_FLOAT, 1, 1),
    E(GL_LINE_SMOOTH, K_BOOL, 1, 0),
    E(GL_CULL_FACE, K_BOOL, 1, 0),
    E(GL_CULL_FACE_MODE, K_ENUM, 1, GL_BACK),
    E(GL_FRONT_FACE, K_ENUM, 1, GL_CCW),
    E(GL_POLYGON_OFFSET_FACTOR, K_FLOAT, 1, 0),
    E(GL_POLYGON_OFFSET_UNITS, K_FLOAT, 1, 0),
    E(GL_POLYGON_OFFSET_FILL, K_BOOL, 1, 0),
    /* 6.11 multisampling */
    E(GL_MULTISAMPLE, K_BOOL, 1, 1),
    E(GL_SAMPLE_ALPHA_TO_COVERAGE, K_BOOL, 1, 0),
    E(GL_SAMPLE_ALPHA_TO_ONE, K_BOOL, 1, 0),
    E(GL_SAMPLE_COVERAGE, K_BOOL, 1, 0),
    E(GL_SAMPLE_COVERAGE_VALUE, K_FLOAT, 1, 1),
    E(GL_SAMPLE_COVERAGE_INVERT, K_BOOL, 1, 0),
    /* 6.12 textures */
    E(GL_ACTIVE_TEXTURE, K_ENUM, 1, GL_TEXTURE0),
    /* 6.14 pixel operations */
    E(GL_SCISSOR_TEST, K_BOOL, 1, 0),
    E(GL_SCISSOR_BOX, K_ENUM, 4, 0, 0, W, H),
    E(GL_ALPHA_TEST, K_BOOL, 1, 0),
    E(GL_ALPHA_TEST_FUNC, K_ENUM, 1, GL_ALWAYS),
    E(GL_ALPHA_TEST_REF, K_NORM, 1, 0),
    E(GL_STENCIL_TEST, K_BOOL, 1, 0),
    E(GL_STENCIL_FUNC, K_ENUM, 1, GL_ALWAYS),
    E(GL_STENCIL_VALUE_MASK, K_MASK, 1, 0),
    E(GL_STENCIL_REF, K_ENUM, 1, 0),
    E(GL_STENCIL_FAIL, K_ENUM, 1, GL_KEEP),
    E(GL_STENCIL_PASS_DEPTH_FAIL, K_ENUM, 1, GL_KEEP),
    E(GL_STENCIL_PASS_DEPTH_PASS, K_ENUM, 1, GL_KEEP),
    E(GL_DEPTH_TEST, K_BOOL, 1, 0),
    E(GL_DEPTH_FUNC, K_ENUM, 1, GL_LESS),
    E(GL_BLEND, K_BOOL, 1, 0),
    E(GL_BLEND_SRC, K_ENUM, 1, GL_ONE),
    E(GL_BLEND_DST, K_ENUM, 1, GL_ZERO),
    E(GL_DITHER, K_BOOL, 1, 1),
    E(GL_COLOR_LOGIC_OP, K_BOOL, 1, 0),
    E(GL_LOGIC_OP_MODE, K_ENUM, 1, GL_COPY),
    /* 6.15 framebuffer control */
    E(GL_COLOR_WRITEMASK, K_BOOL, 4, 1, 1, 1, 1),
    E(GL_DEPTH_WRITEMASK, K_BOOL, 1, 1),
    E(GL_STENCIL_WRITEMASK, K_MASK, 1, 0),
    E(GL_COLOR_CLEAR_VALUE, K_NORM, 4, 0, 0, 0, 0),
    E(GL_DEPTH_CLEAR_VALUE, K_NORM, 1, 1),
    E(GL_STENCIL_CLEAR_VALUE, K_ENUM, 1, 0),
    /* 6.16 pixels */
    E(GL_UNPACK_ALIGNMENT, K_ENUM, 1, 4),
    E(GL_PACK_ALIGNMENT, K_ENUM, 1, 4),
    /* 6.17 hints */
    E(GL_PERSPECTIVE_CORRECTION_HINT, K_ENUM, 1, GL_DONT_CARE),
    E(GL_POINT_SMOOTH_HINT, K_ENUM, 1, GL_DONT_CARE),
    E(GL_LINE_SMOOTH_HINT, K_ENUM, 1, GL_DONT_CARE),
    E(GL_FOG_HINT, K_ENUM, 1, GL_DONT_CARE),
    E(GL_GENERATE_MIPMAP_HINT, K_ENUM, 1, GL_DONT_CARE),
    /* 6.18, 6.19 implementation-dependent values */
    E(GL_MAX_LIGHTS, K_MIN, 1, 8),
    E(GL_MAX_CLIP_PLANES, K_MIN, 1, 1),
    E(GL_MAX_MODELVIEW_STACK_DEPTH, K_MIN, 1, 16),
    E(GL_MAX_PROJECTION_STACK_DEPTH, K_MIN, 1, 2),
    E(GL_MAX_TEXTURE_STACK_DEPTH, K_MIN, 1, 2),
    E(GL_SUBPIXEL_BITS, K_MIN, 1, 4),
    E(GL_MAX_TEXTURE_SIZE, K_MIN, 1, 64),
    E(GL_MAX_VIEWPORT_DIMS, K_MIN, 2, W, H),
    E(GL_ALIASED_POINT_SIZE_RANGE, K_RANGE, 2, 1),
    E(GL_SMOOTH_POINT_SIZE_RANGE, K_RANGE, 2, 1),
    E(GL_ALIASED_LINE_WIDTH_RANGE, K_RANGE, 2, 1),
    E(GL_SMOOTH_LINE_WIDTH_RANGE, K_RANGE, 2, 1),
    E(GL_MAX_TEXTURE_UNITS, K_MIN, 1, 2),
    E(GL_SAMPLE_BUFFERS, K_MIN, 1, 0),
    E(GL_SAMPLES, K_MIN, 1, 0),
    E(GL_NUM_COMPRESSED_TEXTURE_FORMATS, K_MIN, 1, 10),
    E(GL_RED_BITS, K_EXACT, 1, 8),
    E(GL_GREEN_BITS, K_EXACT, 1, 8),
    E(GL_BLUE_BITS, K_EXACT, 1, 8),
    E(GL_ALPHA_BITS, K_EXACT, 1, 8),
    E(GL_DEPTH_BITS, K_MIN, 1, 24),
    E(GL_STENCIL_BITS, K_EXACT, 1, 8),
    X("GL_OES_read_format", GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES, K_MIN, 1, 0),
    X("GL_OES_read_format", GL_IMPLEMENTATION_COLOR_READ_TYPE_OES, K_MIN, 1, 0),
    /* OES_matrix_palette */
    X("GL_OES_matrix_palette", GL_MATRIX_PALETTE_OES, K_BOOL, 1, 0),
    X("GL_OES_matrix_palette", GL_MAX_PALETTE_MATRICES_OES, K_MIN, 1, 9),
    X("GL_OES_matrix_palette", GL_MAX_VERTEX_UNITS_OES, K_MIN, 1, 3),
    X("GL_OES_matrix_palette", GL_CURRENT_PALETTE_MATRIX_OES, K_ENUM, 1, 0),
    X("GL_OES_matrix_palette", GL_MATRIX_INDEX_ARRAY_OES, K_BOOL, 1, 0),
    X("GL_OES_matrix_palette", GL_MATRIX_INDEX_ARRAY_SIZE_OES, K_ENUM, 1, 0),
    X("GL_OES_matrix_palette", GL_MATRIX_INDEX_ARRAY_TYPE_OES, K_ENUM, 1, GL_UNSIGNED_BYTE),
    X("GL_OES_matrix_palette", GL_MATRIX_INDEX_ARRAY_STRIDE_OES, K_ENUM, 1, 0),
    X("GL_OES_matrix_palette", GL_MATRIX_INDEX_ARRAY_BUFFER_BINDING_OES, K_ENUM, 1, 0),
    X("GL_OES_matrix_palette", GL_WEIGHT_ARRAY_OES, K_BOOL, 1, 0),
    X("GL_OES_matrix_palette", GL_WEIGHT_ARRAY_SIZE_OES, K_ENUM, 1, 0),
    X("GL_OES_matrix_palette", GL_WEIGHT_ARRAY_TYPE_OES, K_ENUM, 1, GL_FLOAT),
    X("GL_OES_matrix_palette", GL_WEIGHT_ARRAY_STRIDE_OES, K_ENUM, 1, 0),
    X("GL_OES_matrix_palette", GL_WEIGHT_ARRAY_BUFFER_BINDING_OES, K_ENUM, 1, 0),
    /* OES_blend_* (ES 1.1 extension pack), when listed */
    X("GL_OES_blend_func_separate", GL_BLEND_SRC_RGB_OES, K_ENUM, 1, GL_ONE),
    X("GL_OES_blend_func_separate", GL_BLEND_DST_RGB_OES, K_ENUM, 1, GL_ZERO),
    X("GL_OES_blend_func_separate", GL_BLEND_SRC_ALPHA_OES, K_ENUM, 1, GL_ONE),
    X("GL_OES_blend_func_separate", GL_BLEND_DST_ALPHA_OES, K_ENUM, 1, GL_ZERO),
    X("GL_OES_blend_subtract", GL_BLEND_EQUATION_OES, K_ENUM, 1, GL_FUNC_ADD_OES),
    X("GL_OES_blend_equation_separate", GL_BLEND_EQUATION_ALPHA_OES, K_ENUM, 1,
      GL_FUNC_ADD_OES),
};

static int checked; /* state variables checked */
static const char *extensions;
static int strict; /* ct_strict(), cached */

static int has_ext(const char *name)
{
    const char *p = extensions;
    size_t n = strlen(name);
    while (p && (p = strstr(p, name)) != NULL) {
        if ((p == extensions || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            return 1;
        p += n;
    }
    return 0;
}

static void report(const char *name, const char *what, int i, double got, double want)
{
    char m[256];
    snprintf(m, sizeof m, "%s: %s[%d] is %.9g, expected %.9g", name, what, i, got, want);
    ct_fail(__FILE__, __LINE__, m);
}

/* The fixed-point value of v, clamped (ES 1.1 section 6.1.2). */
static GLfixed to_fixed(double v)
{
    double x = floor(v * 65536.0 + 0.5);
    if (x > INT_MAX)
        return INT_MAX;
    if (x < INT_MIN)
        return INT_MIN;
    return (GLfixed)x;
}

/* The integer a normalized value maps to: [-1, 1] onto [INT_MIN, INT_MAX]. */
static double norm_to_int(double v)
{
    return ((4294967295.0 * v) - 1.0) / 2.0;
}

/*
 * Checks one value of `e` as given by the four getters. f, i, b, x hold the answers.
 */
static void check_value(const struct entry *e, int k, const GLfloat *f, const GLint *i,
                        const GLboolean *b, const GLfixed *x)
{
    double want = e->init[k];
    ++ct.checks;
    switch (e->kind) {
    case K_ENUM:
    case K_EXACT:
        if (i[k] != (GLint)want)
            report(e->name, "GetIntegerv", k, i[k], want);
        if (f[k] != (float)want)
            report(e->name, "GetFloatv", k, f[k], want);
        if (x[k] != to_fixed(want))
            report(e->name, "GetFixedv", k, x[k], to_fixed(want));
        if (b[k] != (want != 0 ? GL_TRUE : GL_FALSE))
            report(e->name, "GetBooleanv", k, b[k], want != 0);
        break;
    case K_BOOL:
        if (b[k] != (want != 0 ? GL_TRUE : GL_FALSE))
            report(e->name, "GetBooleanv", k, b[k], want);
        if (i[k] != (GLint)want)
            report(e->name, "GetIntegerv", k, i[k], want);
        if (f[k] != (float)want)
            report(e->name, "GetFloatv", k, f[k], want);
        if (x[k] != to_fixed(want) && x[k] != (GLfixed)want)
            /* A boolean through GetFixedv: 1.0 in 16.16 (0x10000); some implementations
             * give the raw 1. Either is read as true. */
            report(e->name, "GetFixedv", k, x[k], to_fixed(want));
        break;
    case K_FLOAT:
    case K_NORM:
        if (fabs(f[k] - want) > 1e-6)
            report(e->name, "GetFloatv", k, f[k], want);
        if (abs(x[k] - to_fixed(want)) > 1)
            report(e->name, "GetFixedv", k, x[k], to_fixed(want));
        if (b[k] != (want != 0 ? GL_TRUE : GL_FALSE))
            report(e->name, "GetBooleanv", k, b[k], want != 0);
        if (e->kind == K_FLOAT) {
            if (i[k] != (GLint)floor(want + 0.5)) {
                /* Mesa maps matrix entries through GetIntegerv like colors (1.0 becomes
                 * INT_MAX); ES 1.1 6.1.2 rounds every value that is not a color, depth or
                 * normal. */
                if (e->count == 16 && !strict)
                    fprintf(stderr, "known deviation: %s through GetIntegerv is mapped\n",
                            e->name);
                else
                    report(e->name, "GetIntegerv", k, i[k], floor(want + 0.5));
            }
        } else if (fabs(i[k] - norm_to_int(want)) > 1024.0) {
            report(e->name, "GetIntegerv (normalized)", k, i[k], norm_to_int(want));
        }
        break;
    case K_MIN:
        if (i[k] < (GLint)want)
            report(e->name, "GetIntegerv (minimum)", k, i[k], want);
        /* Consistency with the integer answer. */
        if (f[k] != (float)i[k])
            report(e->name, "GetFloatv vs GetIntegerv", k, f[k], i[k]);
        if (x[k] != to_fixed(i[k]))
            report(e->name, "GetFixedv vs GetIntegerv", k, x[k], to_fixed(i[k]));
        if (b[k] != (i[k] != 0 ? GL_TRUE : GL_FALSE))
            report(e->name, "GetBooleanv vs GetIntegerv", k, b[k], i[k] != 0);
        break;
    case K_RANGE:
        if (k == 0 ? f[0] > want || f[0] <= 0 : f[1] < want || f[1] < f[0])
            report(e->name, "GetFloatv (range)", k, f[k], want);
        if (i[k] != (GLint)floor(f[k] + 0.5))
            report(e->name, "GetIntegerv vs GetFloatv", k, i[k], floor(f[k] + 0.5));
        if (abs(x[k] - to_fixed(f[k])) > 1)
            report(e->name, "GetFixedv vs GetFloatv", k, x[k], to_fixed(f[k]));
        if (b[k] != GL_TRUE)
            report(e->name, "GetBooleanv", k, b[k], 1);
        break;
    case K_MASK:
        if ((i[k] & 0xFF) != 0xFF)
            report(e->name, "GetIntegerv (all ones)", k, i[k], 0xFF);
        if (b[k] != GL_TRUE)
            report(e->name, "GetBooleanv", k, b[k], 1);
        break;
    case K_BITS: {
        float fv = (float)want;
        GLint bits;
        memcpy(&bits, &fv, sizeof bits);
        if (i[k] != bits)
            report(e->name, "GetIntegerv (float bits)", k, i[k], bits);
        break;
    }
    }
}

/* Queries `e` through the four getters and checks every value. */
static void check_entry(const struct entry *e)
{
    GLfloat f[GUARD];
    GLint i[GUARD];
    GLboolean b[GUARD];
    GLfixed x[GUARD];
    int k;

    if (e->ext && !has_ext(e->ext))
        return;
    for (k = 0; k < GUARD; ++k) {
        f[k] = -12345.0f;
        i[k] = -12345;
        b[k] = 0x5A;
        x[k] = -12345;
    }
    glGetIntegerv(e->pname, i);
    CHECK_GL(GL_NO_ERROR);
    if (e->kind != K_BITS) {
        glGetFloatv(e->pname, f);
        CHECK_GL(GL_NO_ERROR);
        glGetBooleanv(e->pname, b);
        CHECK_GL(GL_NO_ERROR);
        glGetFixedv(e->pname, x);
        CHECK_GL(GL_NO_ERROR);
    }
    for (k = e->count; k < GUARD; ++k) {
        ++ct.checks;
        if (i[k] != -12345 || f[k] != -12345.0f || b[k] != 0x5A || x[k] != -12345) {
            report(e->name, "wrote past its count at", k, k, e->count);
            break;
        }
    }
    for (k = 0; k < e->count; ++k)
        check_value(e, k, f, i, b, x);
    ++checked;
}

/* One value through a type-specific getter's float, fixed and (where it exists) int forms. */
static void check_specific(const char *name, int n, const GLfloat *want, const GLfloat *f,
                           const GLfixed *x, const GLint *i, int normalized)
{
    int k;
    for (k = 0; k < n; ++k) {
        ++ct.checks;
        if (fabs(f[k] - want[k]) > 1e-6)
            report(name, "float getter", k, f[k], want[k]);
        if (abs(x[k] - to_fixed(want[k])) > 1)
            report(name, "fixed getter", k, x[k], to_fixed(want[k]));
        if (i && !normalized && i[k] != (GLint)floor(want[k] + 0.5))
            report(name, "integer getter", k, i[k], floor(want[k] + 0.5));
        if (i && normalized && fabs(i[k] - norm_to_int(want[k])) > 1024.0)
            report(name, "integer getter (normalized)", k, i[k], norm_to_int(want[k]));
    }
    ++checked;
}

static void lights_and_material(void)
{
    static const struct {
        GLenum pname;
        const char *name;
        int n;
    } light_params[] = {
        {GL_AMBIENT, "AMBIENT", 4},
        {GL_DIFFUSE, "DIFFUSE", 4},
        {GL_SPECULAR, "SPECULAR", 4},
        {GL_POSITION, "POSITION", 4},
        {GL_SPOT_DIRECTION, "SPOT_DIRECTION", 3},
        {GL_SPOT_EXPONENT, "SPOT_EXPONENT", 1},
        {GL_SPOT_CUTOFF, "SPOT_CUTOFF", 1},
        {GL_CONSTANT_ATTENUATION, "CONSTANT_ATTENUATION", 1},
        {GL_LINEAR_ATTENUATION, "LINEAR_ATTENUATION", 1},
        {GL_QUADRATIC_ATTENUATION, "QUADRATIC_ATTENUATION", 1},
    };
    static const struct {
        GLenum pname;
        const char *name;
        int n;
        GLfloat init[4];
    } material_params[] = {
        {GL_AMBIENT, "material AMBIENT", 4, {0.2f, 0.2f, 0.2f, 1}},
        {GL_DIFFUSE, "material DIFFUSE", 4, {0.8f, 0.8f, 0.8f, 1}},
        {GL_SPECULAR, "material SPECULAR", 4, {0, 0, 0, 1}},
        {GL_EMISSION, "material EMISSION", 4, {0, 0, 0, 1}},
        {GL_SHININESS, "material SHININESS", 1, {0}},
    };
    GLint max_lights = 0, l;
    size_t p;
    glGetIntegerv(GL_MAX_LIGHTS, &max_lights);
    for (l = 0; l < max_lights; ++l) {
        char name[64];
        CHECK(glIsEnabled(GL_LIGHT0 + l) == GL_FALSE);
        ++checked;
        for (p = 0; p < sizeof light_params / sizeof *light_params; ++p) {
            GLfloat want[4] = {0, 0, 0, 1}, f[8];
            GLfixed x[8];
            GLenum pn = light_params[p].pname;
            int k;
            for (k = 0; k < 8; ++k) {
                f[k] = -7.0f;
                x[k] = -7;
            }
            if (pn == GL_DIFFUSE || pn == GL_SPECULAR) {
                if (l == 0)
                    want[0] = want[1] = want[2] = 1;
            } else if (pn == GL_POSITION) {
                want[2] = 1;
                want[3] = 0;
            } else if (pn == GL_SPOT_DIRECTION) {
                want[2] = -1;
            } else if (pn == GL_SPOT_EXPONENT || pn == GL_LINEAR_ATTENUATION ||
                       pn == GL_QUADRATIC_ATTENUATION) {
                want[0] = 0;
            } else if (pn == GL_SPOT_CUTOFF) {
                want[0] = 180;
            } else if (pn == GL_CONSTANT_ATTENUATION) {
                want[0] = 1;
            }
            glGetLightfv(GL_LIGHT0 + l, pn, f);
            CHECK_GL(GL_NO_ERROR);
            glGetLightxv(GL_LIGHT0 + l, pn, x);
            CHECK_GL(GL_NO_ERROR);
            CHECK(f[light_params[p].n] == -7.0f && x[light_params[p].n] == -7);
            snprintf(name, sizeof name, "LIGHT%d %s", (int)l, light_params[p].name);
            check_specific(name, light_params[p].n, want, f, x, NULL, 0);
        }
    }
    for (p = 0; p < sizeof material_params / sizeof *material_params; ++p) {
        GLfloat f[8];
        GLfixed x[8];
        int k;
        for (k = 0; k < 8; ++k) {
            f[k] = -7.0f;
            x[k] = -7;
        }
        glGetMaterialfv(GL_FRONT, material_params[p].pname, f);
        CHECK_GL(GL_NO_ERROR);
        glGetMaterialxv(GL_BACK, material_params[p].pname, x);
        CHECK_GL(GL_NO_ERROR);
        CHECK(f[material_params[p].n] == -7.0f && x[material_params[p].n] == -7);
        check_specific(material_params[p].name, material_params[p].n, material_params[p].init,
                       f, x, NULL, 0);
    }
}

static void texenv_unit(int unit)
{
    static const struct {
        GLenum pname;
        const char *name;
        int n;
        GLfloat init[4];
    } env[] = {
        {GL_TEXTURE_ENV_MODE, "TEXTURE_ENV_MODE", 1, {GL_MODULATE}},
        {GL_TEXTURE_ENV_COLOR, "TEXTURE_ENV_COLOR", 4, {0, 0, 0, 0}},
        {GL_COMBINE_RGB, "COMBINE_RGB", 1, {GL_MODULATE}},
        {GL_COMBINE_ALPHA, "COMBINE_ALPHA", 1, {GL_MODULATE}},
        {GL_SRC0_RGB, "SRC0_RGB", 1, {GL_TEXTURE}},
        {GL_SRC1_RGB, "SRC1_RGB", 1, {GL_PREVIOUS}},
        {GL_SRC2_RGB, "SRC2_RGB", 1, {GL_CONSTANT}},
        {GL_SRC0_ALPHA, "SRC0_ALPHA", 1, {GL_TEXTURE}},
        {GL_SRC1_ALPHA, "SRC1_ALPHA", 1, {GL_PREVIOUS}},
        {GL_SRC2_ALPHA, "SRC2_ALPHA", 1, {GL_CONSTANT}},
        {GL_OPERAND0_RGB, "OPERAND0_RGB", 1, {GL_SRC_COLOR}},
        {GL_OPERAND1_RGB, "OPERAND1_RGB", 1, {GL_SRC_COLOR}},
        {GL_OPERAND2_RGB, "OPERAND2_RGB", 1, {GL_SRC_ALPHA}},
        {GL_OPERAND0_ALPHA, "OPERAND0_ALPHA", 1, {GL_SRC_ALPHA}},
        {GL_OPERAND1_ALPHA, "OPERAND1_ALPHA", 1, {GL_SRC_ALPHA}},
        {GL_OPERAND2_ALPHA, "OPERAND2_ALPHA", 1, {GL_SRC_ALPHA}},
        {GL_RGB_SCALE, "RGB_SCALE", 1, {1}},
        {GL_ALPHA_SCALE, "ALPHA_SCALE", 1, {1}},
    };
    size_t p;
    for (p = 0; p < sizeof env / sizeof *env; ++p) {
        GLfloat f[8];
        GLfixed x[8];
        GLint i[8];
        char name[64];
        int k, is_color = env[p].pname == GL_TEXTURE_ENV_COLOR;
        for (k = 0; k < 8; ++k) {
            f[k] = -7.0f;
            x[k] = -7;
            i[k] = -7;
        }
        glGetTexEnvfv(GL_TEXTURE_ENV, env[p].pname, f);
        CHECK_GL(GL_NO_ERROR);
        glGetTexEnviv(GL_TEXTURE_ENV, env[p].pname, i);
        CHECK_GL(GL_NO_ERROR);
        glGetTexEnvxv(GL_TEXTURE_ENV, env[p].pname, x);
        CHECK_GL(GL_NO_ERROR);
        CHECK(f[env[p].n] == -7.0f && x[env[p].n] == -7 && i[env[p].n] == -7);
        snprintf(name, sizeof name, "unit %d %s", unit, env[p].name);
        if (is_color) {
            check_specific(name, env[p].n, env[p].init, f, x, i, 1);
        } else {
            /* Enums through the fixed getter: the enum's value, as GetFixedv would give. */
            ++ct.checks;
            if (f[0] != env[p].init[0])
                report(name, "glGetTexEnvfv", 0, f[0], env[p].init[0]);
            if (i[0] != (GLint)env[p].init[0])
                report(name, "glGetTexEnviv", 0, i[0], env[p].init[0]);
            if (x[0] != (GLfixed)env[p].init[0] && x[0] != to_fixed(env[p].init[0]))
                report(name, "glGetTexEnvxv", 0, x[0], env[p].init[0]);
            ++checked;
        }
    }
    if (has_ext("GL_OES_point_sprite")) {
        GLint i = -7;
        GLfloat f = -7;
        glGetTexEnviv(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, &i);
        glGetTexEnvfv(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, &f);
        CHECK_GL(GL_NO_ERROR);
        CHECK(i == GL_FALSE && f == 0.0f);
        ++checked;
    }
}

static void texture_object(void)
{
    static const struct {
        GLenum pname;
        const char *name;
        GLfloat init;
    } tp[] = {
        {GL_TEXTURE_MIN_FILTER, "TEXTURE_MIN_FILTER", GL_NEAREST_MIPMAP_LINEAR},
        {GL_TEXTURE_MAG_FILTER, "TEXTURE_MAG_FILTER", GL_LINEAR},
        {GL_TEXTURE_WRAP_S, "TEXTURE_WRAP_S", GL_REPEAT},
        {GL_TEXTURE_WRAP_T, "TEXTURE_WRAP_T", GL_REPEAT},
        {GL_GENERATE_MIPMAP, "GENERATE_MIPMAP", GL_FALSE},
    };
    GLuint names[2] = {0, 0};
    int t;
    size_t p;
    glGenTextures(1, &names[1]);
    for (t = 0; t < 2; ++t) {
        glBindTexture(GL_TEXTURE_2D, names[t]);
        for (p = 0; p < sizeof tp / sizeof *tp; ++p) {
            GLfloat f[2] = {-7, -7};
            GLint i[2] = {-7, -7};
            GLfixed x[2] = {-7, -7};
            char name[64];
            glGetTexParameterfv(GL_TEXTURE_2D, tp[p].pname, f);
            glGetTexParameteriv(GL_TEXTURE_2D, tp[p].pname, i);
            glGetTexParameterxv(GL_TEXTURE_2D, tp[p].pname, x);
            CHECK_GL(GL_NO_ERROR);
            snprintf(name, sizeof name, "texture %u %s", names[t], tp[p].name);
            ++ct.checks;
            if (f[0] != tp[p].init || f[1] != -7)
                report(name, "glGetTexParameterfv", 0, f[0], tp[p].init);
            if (i[0] != (GLint)tp[p].init || i[1] != -7)
                report(name, "glGetTexParameteriv", 0, i[0], tp[p].init);
            if ((x[0] != (GLfixed)tp[p].init && x[0] != to_fixed(tp[p].init)) || x[1] != -7)
                report(name, "glGetTexParameterxv", 0, x[0], tp[p].init);
            ++checked;
        }
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    glDeleteTextures(1, &names[1]);
    CHECK_GL(GL_NO_ERROR);
}

static void buffer_object(void)
{
    GLuint b = 0;
    GLint v = -7;
    glGenBuffers(1, &b);
    glBindBuffer(GL_ARRAY_BUFFER, b);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    CHECK_GL(GL_NO_ERROR);
    CHECK(v == 0);
    ++checked;
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_USAGE, &v);
    CHECK_GL(GL_NO_ERROR);
    CHECK(v == GL_STATIC_DRAW);
    ++checked;
    if (has_ext("GL_OES_mapbuffer")) {
        glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS_OES, &v);
        CHECK_GL(GL_NO_ERROR);
        CHECK(v == GL_WRITE_ONLY_OES);
        ++checked;
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDeleteBuffers(1, &b);
    CHECK_GL(GL_NO_ERROR);
}

static void clip_planes(void)
{
    GLint n = 0, p;
    glGetIntegerv(GL_MAX_CLIP_PLANES, &n);
    for (p = 0; p < n; ++p) {
        static const GLfloat zero[4] = {0, 0, 0, 0};
        GLfloat f[5] = {-7, -7, -7, -7, -7};
        GLfixed x[5] = {-7, -7, -7, -7, -7};
        char name[32];
        glGetClipPlanef(GL_CLIP_PLANE0 + p, f);
        glGetClipPlanex(GL_CLIP_PLANE0 + p, x);
        CHECK_GL(GL_NO_ERROR);
        CHECK(f[4] == -7 && x[4] == -7);
        CHECK(glIsEnabled(GL_CLIP_PLANE0 + p) == GL_FALSE);
        snprintf(name, sizeof name, "CLIP_PLANE%d", (int)p);
        check_specific(name, 4, zero, f, x, NULL, 0);
    }
}

static void pointers(void)
{
    static const struct {
        GLenum pname;
        const char *ext;
    } ptrs[] = {
        {GL_VERTEX_ARRAY_POINTER, NULL},
        {GL_NORMAL_ARRAY_POINTER, NULL},
        {GL_COLOR_ARRAY_POINTER, NULL},
        {GL_TEXTURE_COORD_ARRAY_POINTER, NULL},
        {GL_POINT_SIZE_ARRAY_POINTER_OES, "GL_OES_point_size_array"},
        {GL_MATRIX_INDEX_ARRAY_POINTER_OES, "GL_OES_matrix_palette"},
        {GL_WEIGHT_ARRAY_POINTER_OES, "GL_OES_matrix_palette"},
    };
    size_t p;
    for (p = 0; p < sizeof ptrs / sizeof *ptrs; ++p) {
        void *v = &v;
        if (ptrs[p].ext && !has_ext(ptrs[p].ext))
            continue;
        glGetPointerv(ptrs[p].pname, &v);
        CHECK_GL(GL_NO_ERROR);
        CHECK(v == NULL);
        ++checked;
    }
}

/* Every capability and client array through glIsEnabled, against its initial value. */
static void enables(void)
{
    static const struct {
        GLenum cap;
        GLboolean init;
        const char *ext;
    } caps[] = {
        {GL_ALPHA_TEST, 0, NULL}, {GL_BLEND, 0, NULL}, {GL_COLOR_LOGIC_OP, 0, NULL},
        {GL_COLOR_MATERIAL, 0, NULL}, {GL_CULL_FACE, 0, NULL}, {GL_DEPTH_TEST, 0, NULL},
        {GL_DITHER, 1, NULL}, {GL_FOG, 0, NULL}, {GL_LIGHTING, 0, NULL},
        {GL_LINE_SMOOTH, 0, NULL}, {GL_MULTISAMPLE, 1, NULL}, {GL_NORMALIZE, 0, NULL},
        {GL_POINT_SMOOTH, 0, NULL}, {GL_POLYGON_OFFSET_FILL, 0, NULL},
        {GL_RESCALE_NORMAL, 0, NULL}, {GL_SAMPLE_ALPHA_TO_COVERAGE, 0, NULL},
        {GL_SAMPLE_ALPHA_TO_ONE, 0, NULL}, {GL_SAMPLE_COVERAGE, 0, NULL},
        {GL_SCISSOR_TEST, 0, NULL}, {GL_STENCIL_TEST, 0, NULL}, {GL_TEXTURE_2D, 0, NULL},
        {GL_VERTEX_ARRAY, 0, NULL}, {GL_NORMAL_ARRAY, 0, NULL}, {GL_COLOR_ARRAY, 0, NULL},
        {GL_TEXTURE_COORD_ARRAY, 0, NULL},
        {GL_POINT_SPRITE_OES, 0, "GL_OES_point_sprite"},
        {GL_POINT_SIZE_ARRAY_OES, 0, "GL_OES_point_size_array"},
        {GL_MATRIX_PALETTE_OES, 0, "GL_OES_matrix_palette"},
        {GL_MATRIX_INDEX_ARRAY_OES, 0, "GL_OES_matrix_palette"},
        {GL_WEIGHT_ARRAY_OES, 0, "GL_OES_matrix_palette"},
    };
    size_t p;
    for (p = 0; p < sizeof caps / sizeof *caps; ++p) {
        if (caps[p].ext && !has_ext(caps[p].ext))
            continue;
        CHECK(glIsEnabled(caps[p].cap) == caps[p].init);
        CHECK_GL(GL_NO_ERROR);
        ++checked;
    }
}

int main(void)
{
    GLint units = 0, u, nformats = 0;
    size_t e;
    GLfloat range[2] = {0, 0}, smax = 0, f;

    ct_init(W, H);
    extensions = (const char *)glGetString(GL_EXTENSIONS);
    strict = ct_strict();
    CHECK(extensions != NULL);

    for (e = 0; e < sizeof table / sizeof *table; ++e)
        check_entry(&table[e]);

    /* Per-unit state, each unit made active (and client active) in turn. */
    glGetIntegerv(GL_MAX_TEXTURE_UNITS, &units);
    for (u = 0; u < units; ++u) {
        glActiveTexture(GL_TEXTURE0 + u);
        glClientActiveTexture(GL_TEXTURE0 + u);
        for (e = 0; e < sizeof unit_table / sizeof *unit_table; ++e)
            check_entry(&unit_table[e]);
        texenv_unit(u);
        {
            GLint a = 0, c = 0;
            glGetIntegerv(GL_ACTIVE_TEXTURE, &a);
            glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &c);
            CHECK(a == GL_TEXTURE0 + u && c == GL_TEXTURE0 + u);
        }
    }
    glActiveTexture(GL_TEXTURE0);
    glClientActiveTexture(GL_TEXTURE0);
    CHECK_GL(GL_NO_ERROR);

    /* POINT_SIZE_MAX starts at the largest size either point range allows (ES 1.1 3.3). */
    glGetFloatv(GL_ALIASED_POINT_SIZE_RANGE, range);
    smax = range[1];
    glGetFloatv(GL_SMOOTH_POINT_SIZE_RANGE, range);
    if (range[1] > smax)
        smax = range[1];
    glGetFloatv(GL_POINT_SIZE_MAX, &f);
    CHECK_GL(GL_NO_ERROR);
    CHECK_MESA_DEVIATES(f == smax, "Mesa starts POINT_SIZE_MAX at its own maximum");
    ++checked;

    /* COMPRESSED_TEXTURE_FORMATS: NUM_COMPRESSED_TEXTURE_FORMATS values, the ten paletted
     * formats among them. */
    glGetIntegerv(GL_NUM_COMPRESSED_TEXTURE_FORMATS, &nformats);
    if (nformats > 0 && nformats < 256) {
        GLint formats[256 + 1];
        GLint k, found = 0;
        formats[nformats] = -7;
        glGetIntegerv(GL_COMPRESSED_TEXTURE_FORMATS, formats);
        CHECK_GL(GL_NO_ERROR);
        CHECK(formats[nformats] == -7);
        for (k = 0; k < nformats; ++k)
            found += formats[k] >= GL_PALETTE4_RGB8_OES && formats[k] <= GL_PALETTE8_RGB5_A1_OES;
        CHECK(found == 10);
        ++checked;
    }
    /* OES_read_format: a combination glReadPixels accepts. */
    if (has_ext("GL_OES_read_format")) {
        GLint fmt = 0, type = 0;
        GLubyte px[8];
        glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES, &fmt);
        glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE_OES, &type);
        glReadPixels(0, 0, 1, 1, (GLenum)fmt, (GLenum)type, px);
        CHECK_GL(GL_NO_ERROR);
    }

    lights_and_material();
    texture_object();
    buffer_object();
    clip_planes();
    pointers();
    enables();
    CHECK_GL(GL_NO_ERROR);

    {
        int rc = ct_done(); /* its summary line, then ours last for the harness log */
        printf("%d state variables checked\n", checked);
        return rc;
    }
}
