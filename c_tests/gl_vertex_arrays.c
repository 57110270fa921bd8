/*
 * Geometry inputs in pixels: float and short arrays at odd byte offsets and strides,
 * positions of magnitude 2^20..2^31 (float) and near 2^15 (fixed) scaled back into view,
 * GL_UNSIGNED_INT indices (OES_element_index_uint), the point size array, OES_query_matrix,
 * OES_matrix_get and OES_matrix_palette (through eglGetProcAddress, each only when the
 * extension string names it).
 */
#include "common.h"
#include <GLES/glext.h>

static void setup_view(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrthof(0, 32, 0, 32, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
}

/* The square [8, 24)^2 is white, the pixels around it untouched. */
static void check_square(int dx)
{
    CHECK_PIXEL(8 + dx, 8, 255, 255, 255, 255, 0);
    CHECK_PIXEL(23 + dx, 23, 255, 255, 255, 255, 0);
    CHECK_PIXEL(7 + dx, 8, 0, 0, 0, 0, 0);
    CHECK_PIXEL(24 + dx, 23, 0, 0, 0, 0, 0);
}

static int has_ext(const char *name)
{
    const char *e = (const char *)glGetString(GL_EXTENSIONS);
    return e != NULL && strstr(e, name) != NULL;
}

int main(void)
{
    static const GLfloat sq[8] = {8, 8, 24, 8, 8, 24, 24, 24};
    unsigned char odd[1 + 4 * 10];
    int i;
    ct_init(32, 32);
    glEnableClientState(GL_VERTEX_ARRAY);
    glColor4f(1, 1, 1, 1);

    /* Floats at byte offset 1 with stride 10 (unaligned). */
    setup_view();
    memset(odd, 0, sizeof odd);
    for (i = 0; i < 4; ++i)
        memcpy(odd + 1 + i * 10, &sq[2 * i], 8);
    glVertexPointer(2, GL_FLOAT, 10, odd + 1);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    check_square(0);
    /* Shorts at byte offset 1 with stride 5. */
    setup_view();
    for (i = 0; i < 4; ++i) {
        GLshort s[2];
        s[0] = (GLshort)sq[2 * i];
        s[1] = (GLshort)sq[2 * i + 1];
        memcpy(odd + 1 + i * 5, s, 4);
    }
    glVertexPointer(2, GL_SHORT, 5, odd + 1);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    check_square(0);

    /* Huge float positions scaled back by exact powers of two. */
    {
        static const int exps[3] = {20, 24, 31};
        GLfloat big[8];
        int e, k;
        for (k = 0; k < 3; ++k) {
            e = exps[k];
            setup_view();
            for (i = 0; i < 8; ++i)
                big[i] = sq[i] * (GLfloat)(1u << (e - 3)) / 4.0f;
            /* big = sq * 2^(e-5); scale by 2^(5-e). */
            glScalef(1.0f / (GLfloat)(1u << (e - 5)), 1.0f / (GLfloat)(1u << (e - 5)), 1);
            glVertexPointer(2, GL_FLOAT, 0, big);
            glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
            check_square(0);
        }
        /* Fixed positions up to 24 * 2^10 scaled by 2^-10 (fixed, too). */
        {
            GLfixed fx[8];
            setup_view();
            for (i = 0; i < 8; ++i)
                fx[i] = (GLfixed)(sq[i] * 1024.0f) * 65536;
            glScalex(1 << 6, 1 << 6, 1 << 16); /* 2^-10 */
            glVertexPointer(2, GL_FIXED, 0, fx);
            glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
            check_square(0);
        }
    }

    /* OES_element_index_uint. */
    CHECK(has_ext("GL_OES_element_index_uint"));
    {
        static const GLuint idx[4] = {0, 1, 2, 3};
        setup_view();
        glVertexPointer(2, GL_FLOAT, 0, sq);
        glDrawElements(GL_TRIANGLE_STRIP, 4, GL_UNSIGNED_INT, idx);
        CHECK_GL(GL_NO_ERROR);
        check_square(0);
        ct_save("uint_indices");
    }

    /* Point size array: sizes 1, 3 and 5 at three points (aliased squares). */
    {
        static const GLfloat pts[6] = {4.5f, 16.5f, 14.5f, 16.5f, 26.5f, 16.5f};
        static const GLfloat sizes[3] = {1, 3, 5};
        setup_view();
        glVertexPointer(2, GL_FLOAT, 0, pts);
        glEnableClientState(GL_POINT_SIZE_ARRAY_OES);
        glPointSizePointerOES(GL_FLOAT, 0, sizes);
        glDrawArrays(GL_POINTS, 0, 3);
        glDisableClientState(GL_POINT_SIZE_ARRAY_OES);
        CHECK_PIXEL(4, 16, 255, 255, 255, 255, 0);
        CHECK_PIXEL(5, 16, 0, 0, 0, 0, 0);
        CHECK_PIXEL(13, 15, 255, 255, 255, 255, 0);
        CHECK_PIXEL(12, 16, 0, 0, 0, 0, 0);
        CHECK_PIXEL(24, 14, 255, 255, 255, 255, 0);
        CHECK_PIXEL(28, 18, 255, 255, 255, 255, 0);
        CHECK_PIXEL(23, 16, 0, 0, 0, 0, 0);
        ct_save("point_size_array");
    }

    /* OES_matrix_get: the bit patterns of the modelview. */
    if (has_ext("GL_OES_matrix_get")) {
        GLint bits[16];
        GLfloat f = 0;
        glLoadIdentity();
        glTranslatef(1.5f, 0, 0);
        glGetIntegerv(GL_MODELVIEW_MATRIX_FLOAT_AS_INT_BITS_OES, bits);
        memcpy(&f, &bits[12], 4);
        CHECK(f == 1.5f);
        memcpy(&f, &bits[0], 4);
        CHECK(f == 1.0f);
    }

    /* OES_query_matrix: mantissa * 2^exponent gives each element back. */
    if (has_ext("GL_OES_query_matrix")) {
        PFNGLQUERYMATRIXXOESPROC query =
            (PFNGLQUERYMATRIXXOESPROC)eglGetProcAddress("glQueryMatrixxOES");
        GLfixed m[16];
        GLint e[16];
        CHECK(query != NULL);
        if (query) {
            glLoadIdentity();
            glScalef(100000.0f, 0.5f, 1);
            CHECK(query(m, e) == 0);
            CHECK((double)m[0] / 65536.0 * (double)(1 << e[0]) == 100000.0);
            CHECK((double)m[5] / 65536.0 * (double)(1 << e[5]) == 0.5);
            CHECK((double)m[15] / 65536.0 * (double)(1 << e[15]) == 1.0);
        }
        glLoadIdentity();
    }

    /* OES_matrix_palette: two palette matrices; vertices weighted 1 on matrix 1 (translate
     * x by 4), then 0.5/0.5 between matrix 0 (identity) and 1 (translate by 8) = by 4. */
    if (has_ext("GL_OES_matrix_palette")) {
        PFNGLCURRENTPALETTEMATRIXOESPROC current =
            (PFNGLCURRENTPALETTEMATRIXOESPROC)eglGetProcAddress("glCurrentPaletteMatrixOES");
        PFNGLLOADPALETTEFROMMODELVIEWMATRIXOESPROC load =
            (PFNGLLOADPALETTEFROMMODELVIEWMATRIXOESPROC)eglGetProcAddress(
                "glLoadPaletteFromModelViewMatrixOES");
        PFNGLMATRIXINDEXPOINTEROESPROC index_ptr =
            (PFNGLMATRIXINDEXPOINTEROESPROC)eglGetProcAddress("glMatrixIndexPointerOES");
        PFNGLWEIGHTPOINTEROESPROC weight_ptr =
            (PFNGLWEIGHTPOINTEROESPROC)eglGetProcAddress("glWeightPointerOES");
        static const GLubyte idx1[4] = {1, 1, 1, 1};
        static const GLfloat w1[4] = {1, 1, 1, 1};
        static const GLubyte idx2[8] = {0, 1, 0, 1, 0, 1, 0, 1};
        static const GLfloat w2[8] = {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f};
        GLint v = 0;
        CHECK(current && load && index_ptr && weight_ptr);
        if (current && load && index_ptr && weight_ptr) {
            glGetIntegerv(GL_MAX_PALETTE_MATRICES_OES, &v);
            CHECK(v >= 9);
            glGetIntegerv(GL_MAX_VERTEX_UNITS_OES, &v);
            CHECK(v >= 3);
            setup_view();
            glMatrixMode(GL_MATRIX_PALETTE_OES);
            current(0);
            glLoadIdentity();
            current(1);
            glLoadIdentity();
            glTranslatef(4, 0, 0);
            glGetIntegerv(GL_CURRENT_PALETTE_MATRIX_OES, &v);
            CHECK(v == 1);
            glMatrixMode(GL_MODELVIEW);
            glEnable(GL_MATRIX_PALETTE_OES);
            glEnableClientState(GL_MATRIX_INDEX_ARRAY_OES);
            glEnableClientState(GL_WEIGHT_ARRAY_OES);
            index_ptr(1, GL_UNSIGNED_BYTE, 0, idx1);
            weight_ptr(1, GL_FLOAT, 0, w1);
            glVertexPointer(2, GL_FLOAT, 0, sq);
            glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
            check_square(4);
            /* Matrix 1 from the modelview: translate by 8; weights 0.5 / 0.5. */
            glTranslatef(8, 0, 0);
            glMatrixMode(GL_MATRIX_PALETTE_OES);
            current(1);
            load();
            glMatrixMode(GL_MODELVIEW);
            glLoadIdentity();
            glClear(GL_COLOR_BUFFER_BIT);
            index_ptr(2, GL_UNSIGNED_BYTE, 0, idx2);
            weight_ptr(2, GL_FLOAT, 0, w2);
            glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
            check_square(4);
            glDisable(GL_MATRIX_PALETTE_OES);
            glDisableClientState(GL_MATRIX_INDEX_ARRAY_OES);
            glDisableClientState(GL_WEIGHT_ARRAY_OES);
            /* Errors: index past the palette, too many units. */
            current(1000);
            CHECK_GL(GL_INVALID_VALUE);
            index_ptr(5, GL_UNSIGNED_BYTE, 0, idx2);
            CHECK_GL(GL_INVALID_VALUE);
            weight_ptr(1, GL_UNSIGNED_BYTE, 0, w2);
            CHECK_GL(GL_INVALID_ENUM);
        }
    }
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
