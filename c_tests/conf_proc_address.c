/*
 * conf_proc_address: eglGetProcAddress for every exported function, extensions included
 * (the library lists EGL_KHR_get_all_proc_addresses, so core functions are found too).
 * Every name build.rs lists ($OUT_DIR/entry_points.inc) must give a non-null pointer, and
 * that pointer must be the very function the program links against; names that are not
 * functions give NULL. Then a scene is drawn, and the extensions exercised, only through
 * returned pointers, and the pixels and queries are checked.
 *
 * ct:no-diff (the list is this library's exports; Mesa's libraries export other names)
 */
#define GL_GLEXT_PROTOTYPES 1
#define EGL_EGLEXT_PROTOTYPES 1
#include "common.h"

typedef void (*any_function)(void);

struct entry_point {
    const char *name;
    any_function address;
};

#define EP(name) {#name, (any_function)(name)},
static const struct entry_point entry_points[] = {
#include "entry_points.inc"
};

/* Looks `name` up and casts it to the function pointer type of `var`. */
#define GET(var, type, name)                                                             \
    do {                                                                                 \
        var = (type)eglGetProcAddress(name);                                             \
        CHECK(var != NULL);                                                              \
        if (var == NULL)                                                                 \
            return;                                                                      \
    } while (0)

typedef void(GL_APIENTRYP clear_color_fn)(GLfloat, GLfloat, GLfloat, GLfloat);
typedef void(GL_APIENTRYP clear_fn)(GLbitfield);
typedef void(GL_APIENTRYP read_pixels_fn)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum,
                                          void *);
typedef GLenum(GL_APIENTRYP get_error_fn)(void);
typedef void(GL_APIENTRYP vertex_pointer_fn)(GLint, GLenum, GLsizei, const void *);
typedef void(GL_APIENTRYP enable_client_state_fn)(GLenum);
typedef void(GL_APIENTRYP draw_arrays_fn)(GLenum, GLint, GLsizei);
typedef void(GL_APIENTRYP color4x_fn)(GLfixed, GLfixed, GLfixed, GLfixed);
typedef void(GL_APIENTRYP get_integerv_fn)(GLenum, GLint *);
typedef EGLint(EGLAPIENTRYP egl_get_error_fn)(void);
typedef EGLContext(EGLAPIENTRYP egl_get_current_context_fn)(void);

static void draw_through_pointers(void)
{
    clear_color_fn clear_color;
    clear_fn clear;
    read_pixels_fn read_pixels;
    get_error_fn get_error;
    vertex_pointer_fn vertex_pointer;
    enable_client_state_fn enable_client_state;
    draw_arrays_fn draw_arrays;
    color4x_fn color4x;
    get_integerv_fn get_integerv;
    egl_get_error_fn egl_get_error;
    egl_get_current_context_fn egl_get_current_context;
    PFNGLBLENDEQUATIONOESPROC blend_equation;
    PFNGLQUERYMATRIXXOESPROC query_matrix;
    PFNGLCURRENTPALETTEMATRIXOESPROC current_palette;
    PFNGLCOLOR4XOESPROC color4x_oes;
    static const GLfloat quad[] = {-1, -1, 1, -1, -1, 1, 1, 1};
    GLubyte px[4];
    GLint v = -1;
    GLfixed mantissa[16];
    GLint exponent[16];

    GET(clear_color, clear_color_fn, "glClearColor");
    GET(clear, clear_fn, "glClear");
    GET(read_pixels, read_pixels_fn, "glReadPixels");
    GET(get_error, get_error_fn, "glGetError");
    GET(vertex_pointer, vertex_pointer_fn, "glVertexPointer");
    GET(enable_client_state, enable_client_state_fn, "glEnableClientState");
    GET(draw_arrays, draw_arrays_fn, "glDrawArrays");
    GET(color4x, color4x_fn, "glColor4x");
    GET(get_integerv, get_integerv_fn, "glGetIntegerv");
    GET(egl_get_error, egl_get_error_fn, "eglGetError");
    GET(egl_get_current_context, egl_get_current_context_fn, "eglGetCurrentContext");
    GET(blend_equation, PFNGLBLENDEQUATIONOESPROC, "glBlendEquationOES");
    GET(query_matrix, PFNGLQUERYMATRIXXOESPROC, "glQueryMatrixxOES");
    GET(current_palette, PFNGLCURRENTPALETTEMATRIXOESPROC, "glCurrentPaletteMatrixOES");
    GET(color4x_oes, PFNGLCOLOR4XOESPROC, "glColor4xOES");

    CHECK(egl_get_current_context() == ct.context);
    CHECK(egl_get_error() == EGL_SUCCESS);
    clear_color(0, 0, 1, 1);
    clear(GL_COLOR_BUFFER_BIT);
    read_pixels(3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK(px[0] == 0 && px[1] == 0 && px[2] == 255 && px[3] == 255);

    vertex_pointer(2, GL_FLOAT, 0, quad);
    enable_client_state(GL_VERTEX_ARRAY);
    color4x(0x10000, 0, 0, 0x10000);
    draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    read_pixels(3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK(px[0] == 255 && px[1] == 0 && px[2] == 0);
    color4x_oes(0, 0x10000, 0, 0x10000); /* the OES_fixed_point name of the same call */
    draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    read_pixels(3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK(px[0] == 0 && px[1] == 255 && px[2] == 0);

    blend_equation(GL_FUNC_REVERSE_SUBTRACT_OES);
    get_integerv(GL_BLEND_EQUATION_OES, &v);
    CHECK(v == GL_FUNC_REVERSE_SUBTRACT_OES);
    blend_equation(0x7FFF);
    CHECK(get_error() == GL_INVALID_ENUM);

    current_palette(3);
    get_integerv(GL_CURRENT_PALETTE_MATRIX_OES, &v);
    CHECK(v == 3);

    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glScalef(2, 2, 2);
    CHECK(query_matrix(mantissa, exponent) == 0);
    CHECK((double)mantissa[0] * (double)(1u << (exponent[0] > 0 ? exponent[0] : 0)) ==
          2.0 * 65536.0);
    glLoadIdentity();
    CHECK(get_error() == GL_NO_ERROR);
}

int main(void)
{
    size_t i, n = sizeof entry_points / sizeof *entry_points;
    int found = 0;
    static const char *const not_functions[] = {
        "glNotAFunction", "eglNotAFunction", "", "gl", "glBegin", "glVertex3f",
        "glClearColorOES",
    };

    ct_init(16, 16);
    for (i = 0; i < n; ++i) {
        any_function p = (any_function)eglGetProcAddress(entry_points[i].name);
        ++ct.checks;
        if (p == NULL || p != entry_points[i].address) {
            char m[160];
            snprintf(m, sizeof m, "eglGetProcAddress(\"%s\") is %s", entry_points[i].name,
                     p == NULL ? "NULL" : "not the exported function");
            ct_fail(__FILE__, __LINE__, m);
        } else {
            ++found;
        }
    }
    for (i = 0; i < sizeof not_functions / sizeof *not_functions; ++i)
        CHECK(eglGetProcAddress(not_functions[i]) == NULL);
    CHECK_EGL(EGL_SUCCESS);

    draw_through_pointers();
    CHECK_GL(GL_NO_ERROR);
    ct_save("through_pointers");
    {
        int rc = ct_done(); /* its summary line, then ours last for the harness log */
        printf("eglGetProcAddress: %d of %u exported functions found\n", found, (unsigned)n);
        return rc;
    }
}
