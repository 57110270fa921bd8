/*
 * conf_fuzz: a seeded fuzzer at the C boundary. It issues random GL and EGL calls, valid
 * and invalid, with random arguments, against pbuffer surfaces and contexts it creates,
 * switches, destroys and recreates (some contexts share objects). Every pointer it passes
 * stays within the specification's contract: it points at memory large enough for what the
 * call may read or write, vertex arrays are re-pointed at valid memory before each draw,
 * indices stay within those arrays, and buffer objects always hold 32 KiB whose bytes are
 * 0 or 1 (so indices read from them stay small).
 *
 * After every GL call glGetError must return one of the defined codes and, when it returned
 * an error, GL_NO_ERROR next; after every EGL call eglGetError must return a defined code.
 * A crash, hang or panic fails the harness run; valgrind mode checks memory.
 *
 * CT_FUZZ_SEED (default 1) and CT_FUZZ_CALLS (default 50000: a second natively, a few
 * seconds under valgrind) change the run. Prints the
 * number of calls made.
 */
#include "common.h"

#include <limits.h>
#include <math.h>
#include <stdint.h>

#define MAXS 6 /* surfaces in the pool */
#define MAXC 6 /* contexts in the pool */
#define SCRATCH 65536
#define BUFSIZE 32768

static uint64_t rng_state;
static uint64_t rnd(void)
{
    /* xorshift64* */
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return rng_state * 2685821657736338717ull;
}
static int rn(int n) { return n <= 0 ? 0 : (int)(rnd() % (uint64_t)n); }
static int chance(int percent) { return rn(100) < percent; }

/* Memory every pointer argument points into. */
static unsigned char scratch[SCRATCH];  /* random bytes: client vertex data, texel data */
static unsigned char zero_one[BUFSIZE]; /* 0 or 1: buffer object contents */
static unsigned char out[SCRATCH];      /* what getters and glReadPixels write */
static GLubyte indices8[256];
static GLushort indices16[256];
static GLuint indices32[256];

static const GLenum enums[] = {
    0, 1, 0x7FFF, GL_POINTS, GL_LINES, GL_LINE_LOOP, GL_LINE_STRIP, GL_TRIANGLES,
    GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER,
    GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS, GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR,
    GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_DST_COLOR,
    GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA_SATURATE, GL_CLIP_PLANE0, GL_CLIP_PLANE5, GL_FRONT,
    GL_BACK, GL_FRONT_AND_BACK, GL_FOG, GL_LIGHTING, GL_TEXTURE_2D, GL_CULL_FACE, GL_ALPHA_TEST,
    GL_BLEND, GL_COLOR_LOGIC_OP, GL_DITHER, GL_STENCIL_TEST, GL_DEPTH_TEST, GL_LIGHT0,
    GL_LIGHT7, GL_POINT_SMOOTH, GL_LINE_SMOOTH, GL_SCISSOR_TEST, GL_COLOR_MATERIAL,
    GL_NORMALIZE, GL_RESCALE_NORMAL, GL_POLYGON_OFFSET_FILL, GL_VERTEX_ARRAY, GL_NORMAL_ARRAY,
    GL_COLOR_ARRAY, GL_TEXTURE_COORD_ARRAY, GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE,
    GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE, GL_POINT_SPRITE_OES, GL_MATRIX_PALETTE_OES,
    GL_POINT_SIZE_ARRAY_OES, GL_MATRIX_INDEX_ARRAY_OES, GL_WEIGHT_ARRAY_OES, GL_EXP, GL_EXP2,
    GL_LINEAR, GL_FOG_DENSITY, GL_FOG_START, GL_FOG_END, GL_FOG_MODE, GL_FOG_COLOR, GL_CW,
    GL_CCW, GL_SMOOTH, GL_FLAT, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION,
    GL_SPOT_DIRECTION, GL_SPOT_EXPONENT, GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION,
    GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION, GL_EMISSION, GL_SHININESS,
    GL_AMBIENT_AND_DIFFUSE, GL_LIGHT_MODEL_AMBIENT, GL_LIGHT_MODEL_TWO_SIDE, GL_MODELVIEW,
    GL_PROJECTION, GL_TEXTURE, GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT,
    GL_UNSIGNED_INT, GL_FLOAT, GL_FIXED, GL_ALPHA, GL_RGB, GL_RGBA, GL_LUMINANCE,
    GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT_4_4_4_4, GL_UNSIGNED_SHORT_5_5_5_1,
    GL_UNSIGNED_SHORT_5_6_5, GL_KEEP, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT,
    GL_INCR_WRAP_OES, GL_DECR_WRAP_OES, GL_CLEAR, GL_AND, GL_COPY, GL_XOR, GL_SET,
    GL_NEAREST, GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_TEXTURE_MAG_FILTER,
    GL_TEXTURE_MIN_FILTER, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_GENERATE_MIPMAP,
    GL_REPEAT, GL_CLAMP_TO_EDGE, GL_MIRRORED_REPEAT_OES, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE,
    GL_TEXTURE_ENV_COLOR, GL_MODULATE, GL_DECAL, GL_ADD, GL_COMBINE, GL_ADD_SIGNED,
    GL_INTERPOLATE, GL_SUBTRACT, GL_DOT3_RGB, GL_DOT3_RGBA, GL_COMBINE_RGB, GL_COMBINE_ALPHA,
    GL_SRC0_RGB, GL_SRC1_RGB, GL_SRC2_RGB, GL_SRC0_ALPHA, GL_SRC2_ALPHA, GL_OPERAND0_RGB,
    GL_OPERAND2_ALPHA, GL_RGB_SCALE, GL_ALPHA_SCALE, GL_CONSTANT, GL_PRIMARY_COLOR,
    GL_PREVIOUS, GL_COORD_REPLACE_OES, GL_TEXTURE0, GL_TEXTURE1, GL_TEXTURE3, GL_TEXTURE7,
    GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER, GL_STATIC_DRAW, GL_DYNAMIC_DRAW,
    GL_BUFFER_SIZE, GL_BUFFER_USAGE, GL_BUFFER_ACCESS_OES, GL_WRITE_ONLY_OES, GL_FASTEST,
    GL_NICEST, GL_DONT_CARE, GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_SMOOTH_HINT,
    GL_LINE_SMOOTH_HINT, GL_FOG_HINT, GL_GENERATE_MIPMAP_HINT, GL_PACK_ALIGNMENT,
    GL_UNPACK_ALIGNMENT, GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX, GL_POINT_FADE_THRESHOLD_SIZE,
    GL_POINT_DISTANCE_ATTENUATION, GL_VENDOR, GL_RENDERER, GL_VERSION, GL_EXTENSIONS,
    GL_MODELVIEW_MATRIX, GL_VIEWPORT, GL_COMPRESSED_TEXTURE_FORMATS,
    GL_NUM_COMPRESSED_TEXTURE_FORMATS, GL_CURRENT_COLOR, GL_MAX_TEXTURE_SIZE,
    GL_VERTEX_ARRAY_POINTER, GL_COLOR_ARRAY_POINTER, GL_PALETTE4_RGB8_OES,
    GL_PALETTE8_RGBA8_OES, GL_PALETTE4_R5_G6_B5_OES, GL_PALETTE8_RGB5_A1_OES,
    GL_FUNC_ADD_OES, GL_FUNC_SUBTRACT_OES, GL_FUNC_REVERSE_SUBTRACT_OES,
    GL_IMPLEMENTATION_COLOR_READ_FORMAT_OES, GL_MODELVIEW_MATRIX_FLOAT_AS_INT_BITS_OES,
    GL_MATRIX_INDEX_ARRAY_POINTER_OES, GL_WEIGHT_ARRAY_POINTER_OES,
};

static GLenum re(void)
{
    return chance(3) ? (GLenum)rnd() : enums[rn((int)(sizeof enums / sizeof *enums))];
}
static GLint ri(void)
{
    static const GLint v[] = {0, 1, 2, 3, 4, 8, 16, 63, 64, 65, -1, -2, INT_MAX, INT_MIN,
                              65536, 1 << 20};
    return chance(20) ? (GLint)rnd() : v[rn((int)(sizeof v / sizeof *v))];
}
/* A small size: mostly in [-2, 66]. */
static GLint rsize(void) { return chance(5) ? ri() : rn(69) - 2; }
/* A size for a call that reads or writes client memory of that size: [-3, 66], or one
 * larger than any implementation's limit (so the call must fail before touching memory). */
static GLint rdim(void)
{
    if (chance(97))
        return rn(69) - 2;
    return chance(50) ? -rn(3) - 1 : 1 << 20;
}
static GLfloat rf(void)
{
    static const float v[] = {0.0f, 1.0f, -1.0f, 0.5f, 2.0f, 128.0f, 129.0f, 180.0f, 90.0f,
                              -0.0f, 1e30f, -1e30f, 1e-30f, 65536.0f, 3.5f, 0.25f};
    switch (rn(10)) {
    case 0: return (GLfloat)NAN;
    case 1: return (GLfloat)INFINITY;
    case 2: return (float)rn(2000) / 100.0f - 10.0f;
    default: return v[rn((int)(sizeof v / sizeof *v))];
    }
}
static GLfixed rx(void) { return chance(50) ? (GLfixed)(rf() * 65536.0f) : ri(); }
static GLboolean rb(void) { return (GLboolean)(chance(90) ? rn(2) : rn(256)); }
static GLfloat *rfv(void)
{
    GLfloat *p = (GLfloat *)out + 4096 + rn(64);
    int k;
    for (k = 0; k < 16; ++k)
        p[k] = rf();
    return p;
}
static GLfixed *rxv(void)
{
    GLfixed *p = (GLfixed *)out + 4096 + rn(64);
    int k;
    for (k = 0; k < 16; ++k)
        p[k] = rx();
    return p;
}
static GLint *riv(void)
{
    GLint *p = (GLint *)out + 4096 + rn(64);
    int k;
    for (k = 0; k < 16; ++k)
        p[k] = chance(50) ? (GLint)re() : ri();
    return p;
}
/* A vertex array type, mostly valid ones. */
static GLenum rtype(void)
{
    static const GLenum t[] = {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_FIXED, GL_FLOAT};
    return chance(90) ? t[rn(5)] : re();
}

/* EGL objects. */
static EGLDisplay dpy;
static EGLConfig configs[64];
static EGLint nconfigs;
static EGLSurface surf[MAXS];
static EGLContext ctx[MAXC];
static EGLSurface dead_surf; /* a destroyed handle, reused as a bad argument */
static EGLContext dead_ctx;

static int has_fbo; /* GL_OES_framebuffer_object listed */
static long calls, gl_errors, egl_errors, current_calls, draws;
static int failures_before;

static void check_gl(const char *what)
{
    GLenum e = glGetError();
    ++calls;
    if (eglGetCurrentContext() != EGL_NO_CONTEXT)
        ++current_calls;
    switch (e) {
    case GL_NO_ERROR:
        return;
    case GL_INVALID_ENUM:
    case GL_INVALID_VALUE:
    case GL_INVALID_OPERATION:
    case GL_STACK_OVERFLOW:
    case GL_STACK_UNDERFLOW:
    case GL_OUT_OF_MEMORY:
    case 0x0506: /* GL_INVALID_FRAMEBUFFER_OPERATION_OES, with OES_framebuffer_object */
        if (e == 0x0506 && !has_fbo) {
            ct_fail(__FILE__, __LINE__, "INVALID_FRAMEBUFFER_OPERATION without FBOs");
            return;
        }
        ++gl_errors;
        if (eglGetCurrentContext() != EGL_NO_CONTEXT && glGetError() != GL_NO_ERROR) {
            char m[128];
            snprintf(m, sizeof m, "%s: the error flag did not clear (call %ld)", what, calls);
            ct_fail(__FILE__, __LINE__, m);
        }
        return;
    default: {
        char m[128];
        snprintf(m, sizeof m, "%s: glGetError returned 0x%X (call %ld)", what, (unsigned)e,
                 calls);
        ct_fail(__FILE__, __LINE__, m);
    }
    }
}

static void check_egl(const char *what)
{
    EGLint e = eglGetError();
    ++calls;
    if (e != EGL_SUCCESS)
        ++egl_errors;
    if (e < EGL_SUCCESS || e > EGL_CONTEXT_LOST) {
        char m[128];
        snprintf(m, sizeof m, "%s: eglGetError returned 0x%X (call %ld)", what, (unsigned)e,
                 calls);
        ct_fail(__FILE__, __LINE__, m);
    }
}

#define GL(call)                                                                         \
    do {                                                                                 \
        call;                                                                            \
        check_gl(#call);                                                                 \
    } while (0)
#define EGLC(call)                                                                       \
    do {                                                                                 \
        call;                                                                            \
        check_egl(#call);                                                                \
    } while (0)

static EGLSurface any_surface(void)
{
    if (chance(5))
        return chance(50) ? EGL_NO_SURFACE : dead_surf;
    return surf[rn(MAXS)];
}
static EGLContext any_context(void)
{
    if (chance(5))
        return chance(50) ? EGL_NO_CONTEXT : dead_ctx;
    return ctx[rn(MAXC)];
}

static EGLSurface new_surface(void)
{
    EGLint attribs[16], k = 0;
    EGLConfig c = configs[rn(nconfigs)];
    attribs[k++] = EGL_WIDTH;
    attribs[k++] = chance(95) ? 1 + rn(32) : rsize();
    attribs[k++] = EGL_HEIGHT;
    attribs[k++] = chance(95) ? 1 + rn(32) : rsize();
    if (chance(20)) {
        attribs[k++] = EGL_TEXTURE_FORMAT;
        attribs[k++] = chance(80) ? EGL_TEXTURE_RGBA : (EGLint)re();
        attribs[k++] = EGL_TEXTURE_TARGET;
        attribs[k++] = chance(80) ? EGL_TEXTURE_2D : EGL_NO_TEXTURE;
    }
    if (chance(10)) {
        attribs[k++] = EGL_LARGEST_PBUFFER;
        attribs[k++] = rn(2);
    }
    if (chance(5)) {
        attribs[k++] = (EGLint)re();
        attribs[k++] = ri();
    }
    attribs[k] = EGL_NONE;
    return eglCreatePbufferSurface(dpy, c, attribs);
}

static EGLContext new_context(void)
{
    EGLConfig c = configs[rn(nconfigs)];
    EGLContext share = chance(50) ? ctx[rn(MAXC)] : EGL_NO_CONTEXT;
    EGLint attribs[3] = {EGL_CONTEXT_CLIENT_VERSION, 1, EGL_NONE};
    if (chance(5))
        attribs[1] = rn(4);
    return eglCreateContext(dpy, c, share, chance(50) ? attribs : NULL);
}

static void egl_call(void)
{
    EGLint v = 0;
    int i;
    switch (rn(16)) {
    case 0:
    case 1:
    case 2:
        EGLC(eglMakeCurrent(dpy, any_surface(), any_surface(), any_context()));
        break;
    case 3:
        i = rn(MAXS);
        EGLC(eglDestroySurface(dpy, surf[i]));
        dead_surf = surf[i];
        EGLC(surf[i] = new_surface());
        break;
    case 4:
        i = rn(MAXC);
        EGLC(eglDestroyContext(dpy, ctx[i]));
        dead_ctx = ctx[i];
        EGLC(ctx[i] = new_context());
        break;
    case 5:
        EGLC(eglQuerySurface(dpy, any_surface(), chance(80) ? EGL_WIDTH + rn(40) : (EGLint)re(),
                             &v));
        break;
    case 6:
        EGLC(eglQueryContext(dpy, any_context(), chance(80) ? EGL_CONFIG_ID + rn(200)
                                                            : (EGLint)re(), &v));
        break;
    case 7:
        EGLC(eglSwapBuffers(dpy, any_surface()));
        break;
    case 8:
        EGLC(eglBindTexImage(dpy, any_surface(), chance(90) ? EGL_BACK_BUFFER : ri()));
        break;
    case 9:
        EGLC(eglReleaseTexImage(dpy, any_surface(), chance(90) ? EGL_BACK_BUFFER : ri()));
        break;
    case 10:
        EGLC(eglSurfaceAttrib(dpy, any_surface(),
                              chance(50) ? EGL_MIPMAP_LEVEL : (EGLint)(EGL_SWAP_BEHAVIOR + rn(4)),
                              chance(50) ? rn(4) : (EGLint)re()));
        break;
    case 11:
        EGLC(eglSwapInterval(dpy, ri()));
        break;
    case 12:
        switch (rn(4)) {
        case 0: EGLC(eglWaitGL()); break;
        case 1: EGLC(eglWaitClient()); break;
        case 2: EGLC(eglWaitNative(chance(80) ? EGL_CORE_NATIVE_ENGINE : ri())); break;
        default: EGLC(eglBindAPI(chance(80) ? EGL_OPENGL_ES_API : (EGLenum)re())); break;
        }
        break;
    case 13:
        EGLC(eglGetConfigAttrib(dpy, configs[rn(nconfigs)], EGL_BUFFER_SIZE + rn(64), &v));
        break;
    case 14:
        EGLC((void)eglGetCurrentSurface(chance(80) ? EGL_DRAW + rn(2) : ri()));
        break;
    default:
        EGLC((void)eglQueryString(dpy, EGL_VENDOR + rn(4)));
        break;
    }
}

static PFNGLCURRENTPALETTEMATRIXOESPROC pCurrentPaletteMatrix;
static PFNGLLOADPALETTEFROMMODELVIEWMATRIXOESPROC pLoadPalette;
static PFNGLMATRIXINDEXPOINTEROESPROC pMatrixIndexPointer;
static PFNGLWEIGHTPOINTEROESPROC pWeightPointer;
static PFNGLBLENDEQUATIONOESPROC pBlendEquation;
static PFNGLBLENDFUNCSEPARATEOESPROC pBlendFuncSeparate;
static PFNGLMAPBUFFEROESPROC pMapBuffer;
static PFNGLUNMAPBUFFEROESPROC pUnmapBuffer;
static PFNGLQUERYMATRIXXOESPROC pQueryMatrix;

/* Points every enabled array at valid memory, as the draw about to come will read it. */
static void sane_arrays(void)
{
    GLint units = 1, u, binding = 0, client = GL_TEXTURE0;
    const void *base;
#define PTR() (binding ? (const void *)(intptr_t)rn(256) : (const void *)(scratch + rn(256)))
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &binding);
    glGetIntegerv(GL_MAX_TEXTURE_UNITS, &units);
    glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &client);
    base = PTR();
    glVertexPointer(2 + rn(3), chance(50) ? GL_FLOAT : GL_SHORT, rn(65), base);
    glColorPointer(4, chance(50) ? GL_UNSIGNED_BYTE : GL_FLOAT, rn(65), PTR());
    glNormalPointer(chance(50) ? GL_BYTE : GL_FIXED, rn(65), PTR());
    glPointSizePointerOES(GL_FLOAT, rn(65), PTR());
    for (u = 0; u < units && u < 8; ++u) {
        glClientActiveTexture(GL_TEXTURE0 + u);
        glTexCoordPointer(2 + rn(3), chance(50) ? GL_SHORT : GL_FLOAT, rn(65), PTR());
    }
    glClientActiveTexture((GLenum)client);
    if (pMatrixIndexPointer) {
        pMatrixIndexPointer(1 + rn(3), GL_UNSIGNED_BYTE, rn(17), PTR());
        pWeightPointer(1 + rn(3), GL_FLOAT, rn(17), PTR());
    }
    glGetError(); /* the extension calls may be unknown */
#undef PTR
}

static long trace_from = -1; /* CT_FUZZ_TRACE: describe the arrays of draws from this call */

static void trace_arrays(GLint ebuf)
{
    static const struct {
        GLenum on, ptr, binding, size, type, stride;
        const char *name;
    } a[] = {
        {GL_VERTEX_ARRAY, GL_VERTEX_ARRAY_POINTER, GL_VERTEX_ARRAY_BUFFER_BINDING,
         GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE, GL_VERTEX_ARRAY_STRIDE, "vertex"},
        {GL_COLOR_ARRAY, GL_COLOR_ARRAY_POINTER, GL_COLOR_ARRAY_BUFFER_BINDING,
         GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY_STRIDE, "color"},
        {GL_NORMAL_ARRAY, GL_NORMAL_ARRAY_POINTER, GL_NORMAL_ARRAY_BUFFER_BINDING, 0,
         GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE, "normal"},
        {GL_TEXTURE_COORD_ARRAY, GL_TEXTURE_COORD_ARRAY_POINTER,
         GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, GL_TEXTURE_COORD_ARRAY_SIZE,
         GL_TEXTURE_COORD_ARRAY_TYPE, GL_TEXTURE_COORD_ARRAY_STRIDE, "texcoord (client unit)"},
        {GL_POINT_SIZE_ARRAY_OES, GL_POINT_SIZE_ARRAY_POINTER_OES,
         GL_POINT_SIZE_ARRAY_BUFFER_BINDING_OES, 0, GL_POINT_SIZE_ARRAY_TYPE_OES,
         GL_POINT_SIZE_ARRAY_STRIDE_OES, "point size"},
        {GL_MATRIX_INDEX_ARRAY_OES, GL_MATRIX_INDEX_ARRAY_POINTER_OES,
         GL_MATRIX_INDEX_ARRAY_BUFFER_BINDING_OES, GL_MATRIX_INDEX_ARRAY_SIZE_OES,
         GL_MATRIX_INDEX_ARRAY_TYPE_OES, GL_MATRIX_INDEX_ARRAY_STRIDE_OES, "matrix index"},
        {GL_WEIGHT_ARRAY_OES, GL_WEIGHT_ARRAY_POINTER_OES, GL_WEIGHT_ARRAY_BUFFER_BINDING_OES,
         GL_WEIGHT_ARRAY_SIZE_OES, GL_WEIGHT_ARRAY_TYPE_OES, GL_WEIGHT_ARRAY_STRIDE_OES,
         "weight"},
    };
    size_t k;
    GLint abuf = 0;
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &abuf);
    fprintf(stderr, "call %ld: draw, context %p, ARRAY_BUFFER %d, ELEMENT_ARRAY_BUFFER %d\n",
            calls, (void *)eglGetCurrentContext(), abuf, ebuf);
    if (ebuf && pMapBuffer) {
        GLint size = 0;
        const unsigned char *m;
        glGetBufferParameteriv(GL_ELEMENT_ARRAY_BUFFER, GL_BUFFER_SIZE, &size);
        m = (const unsigned char *)pMapBuffer(GL_ELEMENT_ARRAY_BUFFER, GL_WRITE_ONLY_OES);
        if (m) {
            int i, big = 0;
            for (i = 0; i < 400 && i < size; ++i)
                big += m[i] > 1;
            fprintf(stderr, "  element buffer: %d bytes, %d of the first 400 above 1\n", size,
                    big);
            pUnmapBuffer(GL_ELEMENT_ARRAY_BUFFER);
        } else {
            fprintf(stderr, "  element buffer: %d bytes, cannot map (0x%X)\n", size,
                    glGetError());
        }
    }
    for (k = 0; k < sizeof a / sizeof *a; ++k) {
        void *p = NULL;
        GLint b = 0, size = 0, type = 0, stride = 0;
        if (!glIsEnabled(a[k].on))
            continue;
        glGetPointerv(a[k].ptr, &p);
        glGetIntegerv(a[k].binding, &b);
        if (a[k].size)
            glGetIntegerv(a[k].size, &size);
        glGetIntegerv(a[k].type, &type);
        glGetIntegerv(a[k].stride, &stride);
        fprintf(stderr, "  %s: %p (scratch %+ld) buffer %d size %d type 0x%X stride %d\n",
                a[k].name, p, (long)((unsigned char *)p - scratch), b, size, type, stride);
    }
    glGetError();
}

static void draw_call(void)
{
    GLenum mode = chance(90) ? (GLenum)rn(7) : re();
    GLint ebuf = 0;
    ++draws;
    sane_arrays();
    glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &ebuf);
    if (trace_from >= 0 && calls >= trace_from)
        trace_arrays(ebuf);
    if (chance(50)) {
        GLint first = chance(95) ? rn(128) : ri();
        GLsizei count = chance(95) ? rn(129) : ri();
        /* The arrays hold 256 elements: a draw may not reach past them (a huge `first`
         * with count 0 or a negative count is fine: nothing is read). */
        if (count > 0 && (long)first + (long)count > 256)
            first = rn(257 - (count > 256 ? 256 : count)), count = count > 256 ? 256 : count;
        if (trace_from >= 0 && calls >= trace_from)
            fprintf(stderr, "  glDrawArrays(0x%X, %d, %d)\n", mode, first, count);
        GL(glDrawArrays(mode, first, count));
    } else {
        GLsizei count = chance(95) ? rn(257) : ri();
        GLenum type;
        const void *p;
        if (count > 256)
            count = 256;
        if (ebuf) {
            /* Offsets into the bound buffer, whose bytes are 0 or 1: indices <= 257. */
            type = chance(50) ? GL_UNSIGNED_BYTE : GL_UNSIGNED_SHORT;
            p = (const void *)(intptr_t)(2 * rn(64));
        } else {
            switch (rn(4)) {
            case 0: type = GL_UNSIGNED_BYTE; p = indices8; break;
            case 1: type = GL_UNSIGNED_SHORT; p = indices16; break;
            case 2: type = GL_UNSIGNED_INT; p = indices32; break;
            default: type = re(); p = indices32; break;
            }
        }
        if (trace_from >= 0 && calls >= trace_from)
            fprintf(stderr, "  glDrawElements(0x%X, %d, 0x%X, %p)\n", mode, count, type, p);
        GL(glDrawElements(mode, count, type, p));
    }
}

static void texture_call(void)
{
    GLenum target = chance(90) ? GL_TEXTURE_2D : re();
    GLint level = chance(80) ? rn(4) : ri();
    GLenum fmt = chance(80) ? GL_ALPHA + (GLenum)rn(5) : re();
    GLint w = chance(70) ? 1 << rn(6) : rdim(), h = chance(70) ? 1 << rn(6) : rdim();
    switch (rn(8)) {
    case 0:
        GL(glTexImage2D(target, level, (GLint)(chance(90) ? fmt : re()), w, h, chance(95) ? 0 : ri(),
                        fmt, chance(70) ? GL_UNSIGNED_BYTE : re(),
                        chance(90) ? (const void *)scratch : NULL));
        break;
    case 1:
        GL(glTexSubImage2D(target, level, rsize(), rsize(), w, h, fmt,
                           chance(70) ? GL_UNSIGNED_BYTE : re(), scratch));
        break;
    case 2:
        GL(glCopyTexImage2D(target, level, fmt, rsize(), rsize(), w, h, chance(95) ? 0 : ri()));
        break;
    case 3:
        GL(glCopyTexSubImage2D(target, level, rsize(), rsize(), rsize(), rsize(), w, h));
        break;
    case 4:
        GL(glCompressedTexImage2D(target, chance(70) ? -rn(3) : level,
                                  chance(80) ? GL_PALETTE4_RGB8_OES + (GLenum)rn(10) : re(), w, h,
                                  chance(95) ? 0 : ri(), rn(4097), scratch));
        break;
    case 5:
        GL(glCompressedTexSubImage2D(target, level, rsize(), rsize(), w, h, re(), rn(4097),
                                     scratch));
        break;
    case 6: {
        GLuint names[4];
        GLsizei n = chance(95) ? rn(5) : -1;
        if (chance(50)) {
            GL(glGenTextures(n, names));
            if (n > 0)
                GL(glBindTexture(target, names[0]));
        } else {
            names[0] = (GLuint)rn(8);
            names[1] = (GLuint)rn(8);
            names[2] = (GLuint)rn(8);
            names[3] = (GLuint)rn(8);
            GL(glDeleteTextures(n, names));
        }
        break;
    }
    default:
        GL(glBindTexture(target, (GLuint)rn(8)));
        break;
    }
}

static void buffer_call(void)
{
    GLenum target = chance(90) ? GL_ARRAY_BUFFER + (GLenum)rn(2) : re();
    switch (rn(6)) {
    case 0: {
        GLuint names[4];
        GLsizei n = chance(95) ? rn(5) : -1;
        GL(glGenBuffers(n, names));
        if (n > 0) {
            GL(glBindBuffer(target, names[0]));
            GL(glBufferData(target, BUFSIZE, zero_one, GL_STATIC_DRAW));
        }
        break;
    }
    case 1: {
        GLuint names[4] = {(GLuint)rn(8), (GLuint)rn(8), (GLuint)rn(8), (GLuint)rn(8)};
        GL(glDeleteBuffers(chance(95) ? rn(5) : -1, names));
        break;
    }
    case 2: {
        GLuint b = (GLuint)rn(8);
        GL(glBindBuffer(target, b));
        /* A name bound for the first time has no store: give it the usual one. */
        if (b != 0 && target <= GL_ELEMENT_ARRAY_BUFFER && target >= GL_ARRAY_BUFFER) {
            GLint size = 0;
            glGetBufferParameteriv(target, GL_BUFFER_SIZE, &size);
            if (size < BUFSIZE)
                GL(glBufferData(target, BUFSIZE, zero_one, GL_DYNAMIC_DRAW));
        }
        break;
    }
    case 3:
        GL(glBufferData(target, chance(90) ? BUFSIZE : -rn(5) - 1,
                        zero_one, /* never NULL: indices read from buffers must stay small */
                        chance(90) ? GL_STATIC_DRAW + (GLenum)rn(2) * 4 : re()));
        break;
    case 4:
        GL(glBufferSubData(target, chance(90) ? rn(BUFSIZE) : ri(), chance(90) ? rn(512) : -rn(3) - 1,
                           zero_one));
        break;
    default: {
        GLint v = 0;
        GL(glGetBufferParameteriv(target, re(), &v));
        if (pMapBuffer && chance(50)) {
            GLint size = 0;
            void *m;
            glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &size);
            glGetError();
            GL(m = pMapBuffer(GL_ARRAY_BUFFER, chance(90) ? GL_WRITE_ONLY_OES : re()));
            if (m != NULL && size > 0)
                memset(m, rn(2), (size_t)(size < 64 ? size : 64));
            if (chance(80))
                GL(pUnmapBuffer(GL_ARRAY_BUFFER));
        }
        break;
    }
    }
}

static void query_call(void)
{
    void *p = NULL;
    switch (rn(12)) {
    case 0: GL(glGetBooleanv(re(), (GLboolean *)out)); break;
    case 1: GL(glGetIntegerv(re(), (GLint *)out)); break;
    case 2: GL(glGetFloatv(re(), (GLfloat *)out)); break;
    case 3: GL(glGetFixedv(re(), (GLfixed *)out)); break;
    case 4: GL((void)glGetString(re())); break;
    case 5: GL(glGetPointerv(re(), &p)); break;
    case 6: GL(glGetLightfv(GL_LIGHT0 + (GLenum)rn(9), re(), (GLfloat *)out)); break;
    case 7: GL(glGetMaterialxv(re(), re(), (GLfixed *)out)); break;
    case 8: GL(glGetTexEnviv(re(), re(), (GLint *)out)); break;
    case 9: GL(glGetTexParameterfv(re(), re(), (GLfloat *)out)); break;
    case 10: GL(glGetClipPlanef(GL_CLIP_PLANE0 + (GLenum)rn(8), (GLfloat *)out)); break;
    default:
        GL((void)glIsEnabled(re()));
        GL((void)glIsTexture((GLuint)rn(8)));
        GL((void)glIsBuffer((GLuint)rn(8)));
        break;
    }
}

static void state_call(void)
{
    switch (rn(60)) {
    case 0: GL(glEnable(re())); break;
    case 1: GL(glDisable(re())); break;
    case 2: GL(glEnableClientState(re())); break;
    case 3: GL(glDisableClientState(re())); break;
    case 4: GL(glActiveTexture(chance(90) ? GL_TEXTURE0 + (GLenum)rn(5) : re())); break;
    case 5: GL(glClientActiveTexture(chance(90) ? GL_TEXTURE0 + (GLenum)rn(5) : re())); break;
    case 6: GL(glAlphaFunc(re(), rf())); break;
    case 7: GL(glBlendFunc(re(), re())); break;
    case 8: GL(glDepthFunc(re())); break;
    case 9: GL(glStencilFunc(re(), ri(), (GLuint)ri())); break;
    case 10: GL(glStencilOp(re(), re(), re())); break;
    case 11: GL(glLogicOp(re())); break;
    case 12: GL(glCullFace(re())); break;
    case 13: GL(glFrontFace(re())); break;
    case 14: GL(glShadeModel(re())); break;
    case 15: GL(glHint(re(), re())); break;
    case 16: GL(glClearColor(rf(), rf(), rf(), rf())); break;
    case 17: GL(glClear((GLbitfield)(chance(90) ? rn(0x4500) & 0x4500 : (GLbitfield)rnd()))); break;
    case 18: GL(glClearDepthx(rx())); break;
    case 19: GL(glClearStencil(ri())); break;
    case 20: GL(glColorMask(rb(), rb(), rb(), rb())); break;
    case 21: GL(glDepthMask(rb())); break;
    case 22: GL(glStencilMask((GLuint)ri())); break;
    case 23: GL(glDepthRangef(rf(), rf())); break;
    case 24: GL(glViewport(rsize(), rsize(), rsize(), rsize())); break;
    case 25: GL(glScissor(rsize(), rsize(), rsize(), rsize())); break;
    case 26: GL(glPixelStorei(re(), ri())); break;
    case 27: GL(glLineWidth(rf())); break;
    case 28: GL(glPointSize(rf())); break;
    case 29: GL(glPointParameterf(re(), rf())); break;
    case 30: GL(glPointParameterxv(re(), rxv())); break;
    case 31: GL(glPolygonOffset(rf(), rf())); break;
    case 32: GL(glSampleCoverage(rf(), rb())); break;
    case 33: GL(glMatrixMode(chance(90) ? GL_MODELVIEW + (GLenum)rn(3) : re())); break;
    case 34: GL(glPushMatrix()); break;
    case 35: GL(glPopMatrix()); break;
    case 36: GL(glLoadIdentity()); break;
    case 37: GL(glLoadMatrixf(rfv())); break;
    case 38: GL(glMultMatrixx(rxv())); break;
    case 39: GL(glRotatef(rf(), rf(), rf(), rf())); break;
    case 40: GL(glTranslatex(rx(), rx(), rx())); break;
    case 41: GL(glScalef(rf(), rf(), rf())); break;
    case 42: GL(glFrustumf(rf(), rf(), rf(), rf(), rf(), rf())); break;
    case 43: GL(glOrthox(rx(), rx(), rx(), rx(), rx(), rx())); break;
    case 44: GL(glClipPlanef(GL_CLIP_PLANE0 + (GLenum)rn(8), rfv())); break;
    case 45: GL(glFogf(re(), rf())); break;
    case 46: GL(glFogxv(re(), rxv())); break;
    case 47: GL(glLightf(GL_LIGHT0 + (GLenum)rn(9), re(), rf())); break;
    case 48: GL(glLightfv(GL_LIGHT0 + (GLenum)rn(9), re(), rfv())); break;
    case 49: GL(glLightModelxv(re(), rxv())); break;
    case 50: GL(glMaterialf(re(), re(), rf())); break;
    case 51: GL(glMaterialfv(GL_FRONT_AND_BACK, re(), rfv())); break;
    case 52: GL(glTexEnvi(re(), re(), (GLint)re())); break;
    case 53: GL(glTexEnvfv(re(), re(), rfv())); break;
    case 54: GL(glTexParameteri(GL_TEXTURE_2D, re(), (GLint)re())); break;
    case 55: GL(glTexParameterxv(re(), re(), (const GLfixed *)riv())); break;
    case 56: GL(glColor4f(rf(), rf(), rf(), rf())); break;
    case 57: GL(glNormal3x(rx(), rx(), rx())); break;
    case 58: GL(glMultiTexCoord4f(re(), rf(), rf(), rf(), rf())); break;
    default:
        if (pCurrentPaletteMatrix) {
            GL(pCurrentPaletteMatrix((GLuint)rn(40)));
            GL(pLoadPalette());
        }
        if (pBlendEquation) {
            GL(pBlendEquation(re()));
            GL(pBlendFuncSeparate(re(), re(), re(), re()));
        }
        if (pQueryMatrix)
            GL((void)pQueryMatrix((GLfixed *)out, (GLint *)out + 16));
        break;
    }
}

/* A vertex array call with random arguments (no draw follows before sane_arrays). */
static void pointer_call(void)
{
    GLint binding = 0;
    const void *p;
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &binding);
    p = binding ? (const void *)(intptr_t)rn(256) : (const void *)(scratch + rn(256));
    switch (rn(5)) {
    case 0: GL(glVertexPointer(rn(6), rtype(), chance(95) ? rn(65) : ri(), p)); break;
    case 1: GL(glColorPointer(rn(6), rtype(), chance(95) ? rn(65) : ri(), p)); break;
    case 2: GL(glNormalPointer(rtype(), chance(95) ? rn(65) : ri(), p)); break;
    case 3: GL(glTexCoordPointer(rn(6), rtype(), chance(95) ? rn(65) : ri(), p)); break;
    default: GL(glPointSizePointerOES(rtype(), chance(95) ? rn(65) : ri(), p)); break;
    }
}

static void read_call(void)
{
    /* glReadPixels has no size limit: the memory must hold all of w x h. */
    GLsizei w = chance(95) ? rn(40) : rn(69) - 2, h = chance(95) ? rn(40) : rn(69) - 2;
    GL(glReadPixels(rsize(), rsize(), w, h, chance(80) ? GL_RGBA : re(),
                    chance(80) ? GL_UNSIGNED_BYTE : re(), out));
    if (chance(30))
        GL(glFlush());
    if (chance(10))
        GL(glFinish());
}

int main(void)
{
    const char *seed_env = getenv("CT_FUZZ_SEED");
    const char *calls_env = getenv("CT_FUZZ_CALLS");
    unsigned long seed = seed_env ? strtoul(seed_env, NULL, 0) : 1;
    long target = calls_env ? atol(calls_env) : 50000;
    const char *trace_env = getenv("CT_FUZZ_TRACE");
    EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                        EGL_OPENGL_ES_BIT, EGL_NONE};
    int i;

    trace_from = trace_env ? atol(trace_env) : -1;
    rng_state = seed * 0x9E3779B97F4A7C15ull + 1;
    for (i = 0; i < SCRATCH; ++i)
        scratch[i] = (unsigned char)rnd();
    for (i = 0; i < BUFSIZE; ++i)
        zero_one[i] = (unsigned char)rn(2);
    for (i = 0; i < 256; ++i) {
        indices8[i] = (GLubyte)rn(256);
        indices16[i] = (GLushort)rn(256);
        indices32[i] = (GLuint)rn(256);
    }
    /* Through ct_init, so ct_done tears down what it made; the fuzz pool is separate. */
    ct_init(16, 16);
    dpy = ct.display;
    if (!eglChooseConfig(dpy, attribs, configs, 64, &nconfigs) || nconfigs < 1) {
        fprintf(stderr, "no pbuffer configs\n");
        return 2;
    }
    pCurrentPaletteMatrix =
        (PFNGLCURRENTPALETTEMATRIXOESPROC)eglGetProcAddress("glCurrentPaletteMatrixOES");
    pLoadPalette = (PFNGLLOADPALETTEFROMMODELVIEWMATRIXOESPROC)eglGetProcAddress(
        "glLoadPaletteFromModelViewMatrixOES");
    pMatrixIndexPointer =
        (PFNGLMATRIXINDEXPOINTEROESPROC)eglGetProcAddress("glMatrixIndexPointerOES");
    pWeightPointer = (PFNGLWEIGHTPOINTEROESPROC)eglGetProcAddress("glWeightPointerOES");
    pBlendEquation = (PFNGLBLENDEQUATIONOESPROC)eglGetProcAddress("glBlendEquationOES");
    pBlendFuncSeparate =
        (PFNGLBLENDFUNCSEPARATEOESPROC)eglGetProcAddress("glBlendFuncSeparateOES");
    pMapBuffer = (PFNGLMAPBUFFEROESPROC)eglGetProcAddress("glMapBufferOES");
    pUnmapBuffer = (PFNGLUNMAPBUFFEROESPROC)eglGetProcAddress("glUnmapBufferOES");
    pQueryMatrix = (PFNGLQUERYMATRIXXOESPROC)eglGetProcAddress("glQueryMatrixxOES");
    if (!pCurrentPaletteMatrix || !pLoadPalette || !pMatrixIndexPointer || !pWeightPointer)
        pCurrentPaletteMatrix = NULL, pMatrixIndexPointer = NULL;
    if (!pBlendEquation || !pBlendFuncSeparate)
        pBlendEquation = NULL;
    if (!pMapBuffer || !pUnmapBuffer)
        pMapBuffer = NULL;
    /* Mesa's eglGetProcAddress answers non-NULL for any gl* name: keep only listed ones. */
    {
        const char *ext = (const char *)glGetString(GL_EXTENSIONS);
        if (!strstr(ext, "GL_OES_matrix_palette"))
            pCurrentPaletteMatrix = NULL, pMatrixIndexPointer = NULL;
        if (!strstr(ext, "GL_OES_blend_func_separate") || !strstr(ext, "GL_OES_blend_subtract"))
            pBlendEquation = NULL;
        if (!strstr(ext, "GL_OES_mapbuffer"))
            pMapBuffer = NULL;
        if (!strstr(ext, "GL_OES_query_matrix"))
            pQueryMatrix = NULL;
        has_fbo = strstr(ext, "GL_OES_framebuffer_object") != NULL;
    }
    /* Regression: a scissor box wholly left of the surface, with negative corners, made
     * glClear panic on a rasterizer thread. It clears nothing. */
    {
        GLubyte px[4] = {0, 0, 0, 0};
        glClearColor(0, 1, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glEnable(GL_SCISSOR_TEST);
        glScissor(INT_MIN, INT_MIN, 5, 5);
        glClearColor(1, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        CHECK(px[0] == 0 && px[1] == 255);
        glDisable(GL_SCISSOR_TEST);
        CHECK_GL(GL_NO_ERROR);
    }
    for (i = 0; i < MAXS; ++i)
        surf[i] = new_surface();
    for (i = 0; i < MAXC; ++i)
        ctx[i] = new_context();
    dead_surf = surf[0];
    dead_ctx = ctx[0];
    eglGetError();
    failures_before = ct.failures;

    while (calls < target && ct.failures - failures_before < 20) {
        int k = rn(100);
        /* Mostly keep a context current, so most GL calls reach one. */
        if (eglGetCurrentContext() == EGL_NO_CONTEXT && chance(50)) {
            EGLSurface s = surf[rn(MAXS)];
            EGLC(eglMakeCurrent(dpy, s, s, ctx[rn(MAXC)]));
            continue;
        }
        if (k < 8)
            egl_call();
        else if (k < 20)
            draw_call();
        else if (k < 28)
            texture_call();
        else if (k < 36)
            buffer_call();
        else if (k < 50)
            query_call();
        else if (k < 58)
            pointer_call();
        else if (k < 62)
            read_call();
        else
            state_call();
    }

    /* Tear down everything the pool holds; ct_done releases the rest. */
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    for (i = 0; i < MAXS; ++i)
        eglDestroySurface(dpy, surf[i]);
    for (i = 0; i < MAXC; ++i)
        eglDestroyContext(dpy, ctx[i]);
    eglGetError();
    CHECK(eglMakeCurrent(dpy, ct.surface, ct.surface, ct.context));
    CHECK_GL(GL_NO_ERROR);
    {
        int rc = ct_done(); /* its summary line, then ours last for the harness log */
        printf("seed %lu: %ld calls (%ld GL calls with a current context, %ld draws; %ld GL "
               "errors, %ld EGL errors raised)\n",
               seed, calls, current_calls, draws, gl_errors, egl_errors);
        return rc;
    }
}
