/*
 * OES_texture_cube_map: each face sampled along its axis exactly with NEAREST (every texel
 * of every face, the face and its (s, t) from the extension's table), cube maps taking
 * precedence over 2D on a unit, glTexSubImage2D and glCopyTexImage2D on faces, texture
 * coordinate generation (REFLECTION_MAP on a flat quad facing the viewer samples the +Z
 * face, NORMAL_MAP samples where the normal points), incompleteness from mismatched faces,
 * queries, every glTexGen*OES / glGetTexGen*OES entry point, and the errors: non-square face
 * images (INVALID_VALUE), a 2D name bound as a cube map (INVALID_OPERATION), bad targets,
 * coordinates and modes (INVALID_ENUM).
 */
#include "common.h"

#define W 32
#define H 32
#define N 2

/* Extension functions through eglGetProcAddress (Mesa exports them only that way). */
static PFNGLTEXGENFOESPROC glTexGenfOES;
static PFNGLTEXGENFVOESPROC glTexGenfvOES;
static PFNGLTEXGENIOESPROC glTexGeniOES;
static PFNGLTEXGENIVOESPROC glTexGenivOES;
static PFNGLTEXGENXOESPROC glTexGenxOES;
static PFNGLTEXGENXVOESPROC glTexGenxvOES;
static PFNGLGETTEXGENFVOESPROC glGetTexGenfvOES;
static PFNGLGETTEXGENIVOESPROC glGetTexGenivOES;
static PFNGLGETTEXGENXVOESPROC glGetTexGenxvOES;

static void load(void)
{
    glTexGenfOES = (PFNGLTEXGENFOESPROC)eglGetProcAddress("glTexGenfOES");
    glTexGenfvOES = (PFNGLTEXGENFVOESPROC)eglGetProcAddress("glTexGenfvOES");
    glTexGeniOES = (PFNGLTEXGENIOESPROC)eglGetProcAddress("glTexGeniOES");
    glTexGenivOES = (PFNGLTEXGENIVOESPROC)eglGetProcAddress("glTexGenivOES");
    glTexGenxOES = (PFNGLTEXGENXOESPROC)eglGetProcAddress("glTexGenxOES");
    glTexGenxvOES = (PFNGLTEXGENXVOESPROC)eglGetProcAddress("glTexGenxvOES");
    glGetTexGenfvOES = (PFNGLGETTEXGENFVOESPROC)eglGetProcAddress("glGetTexGenfvOES");
    glGetTexGenivOES = (PFNGLGETTEXGENIVOESPROC)eglGetProcAddress("glGetTexGenivOES");
    glGetTexGenxvOES = (PFNGLGETTEXGENXVOESPROC)eglGetProcAddress("glGetTexGenxvOES");
}

/* Texel (i, j) of face f (0 = POSITIVE_X .. 5 = NEGATIVE_Z). */
static void face_texel(int f, int i, int j, GLubyte out[4])
{
    out[0] = (GLubyte)(f * 40 + 10);
    out[1] = (GLubyte)(i * 100 + 50);
    out[2] = (GLubyte)(j * 100 + 50);
    out[3] = 255;
}

static void upload_faces(void)
{
    GLubyte img[N * N * 4];
    int f, i, j;
    for (f = 0; f < 6; ++f) {
        for (j = 0; j < N; ++j)
            for (i = 0; i < N; ++i)
                face_texel(f, i, j, &img[(j * N + i) * 4]);
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X_OES + f, 0, GL_RGBA, N, N, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, img);
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP_OES, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP_OES, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

/* The extension's table: the face and (s, t) direction (x, y, z) selects. */
static int lookup(float x, float y, float z, float *s, float *t)
{
    float ax = x < 0 ? -x : x, ay = y < 0 ? -y : y, az = z < 0 ? -z : z;
    float sc, tc, ma;
    int f;
    if (ax >= ay && ax >= az) {
        f = x >= 0 ? 0 : 1;
        sc = x >= 0 ? -z : z;
        tc = -y;
        ma = ax;
    } else if (ay >= az) {
        f = y >= 0 ? 2 : 3;
        sc = x;
        tc = y >= 0 ? z : -z;
        ma = ay;
    } else {
        f = z >= 0 ? 4 : 5;
        sc = z >= 0 ? x : -x;
        tc = -y;
        ma = az;
    }
    *s = (sc / ma + 1) / 2;
    *t = (tc / ma + 1) / 2;
    return f;
}

static void full_quad(void)
{
    static const GLfloat v[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

static void check_direction(float x, float y, float z)
{
    float s, t;
    int f = lookup(x, y, z, &s, &t);
    GLubyte e[4];
    face_texel(f, (int)(s * N), (int)(t * N), e);
    glMultiTexCoord4f(GL_TEXTURE0, x, y, z, 1);
    full_quad();
    CHECK_PIXEL(W / 2, H / 2, e[0], e[1], e[2], e[3], 0);
}

static void every_face_along_its_axis(void)
{
    static const float o[2] = {-0.5f, 0.5f};
    int axis, sign, a, b;
    for (axis = 0; axis < 3; ++axis)
        for (sign = 0; sign < 2; ++sign)
            for (a = 0; a < 2; ++a)
                for (b = 0; b < 2; ++b) {
                    float d[3];
                    d[axis] = sign ? -1.0f : 1.0f;
                    d[(axis + 1) % 3] = o[a];
                    d[(axis + 2) % 3] = o[b];
                    check_direction(d[0], d[1], d[2]);
                }
    /* q only scales the direction; a longer direction picks the same texel. */
    glMultiTexCoord4f(GL_TEXTURE0, -4, 2, 2, 2);
    full_quad();
    {
        GLubyte e[4];
        face_texel(1, 1, 0, e);
        CHECK_PIXEL(3, 3, e[0], e[1], e[2], e[3], 0);
    }
    CHECK_GL(GL_NO_ERROR);
    ct_save("faces");
}

static void sub_image_copy_and_precedence(GLuint tex2d)
{
    static const GLubyte green[4] = {0, 255, 0, 255};
    GLubyte e[4];
    /* TexSubImage2D on NEGATIVE_Y's texel (1, 0). */
    glTexSubImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y_OES, 0, 1, 0, 1, 1, GL_RGBA,
                    GL_UNSIGNED_BYTE, green);
    glMultiTexCoord4f(GL_TEXTURE0, 0.5f, -1, 0.5f, 1);
    full_quad();
    CHECK_PIXEL(5, 5, 0, 255, 0, 255, 0);
    /* CopyTexImage2D into NEGATIVE_Z from a cleared surface. */
    glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glCopyTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z_OES, 0, GL_RGBA, 0, 0, N, N, 0);
    CHECK_GL(GL_NO_ERROR);
    glMultiTexCoord4f(GL_TEXTURE0, 0.1f, 0.1f, -1, 1);
    full_quad();
    CHECK_PIXEL(5, 5, 51, 102, 153, 255, 0);
    /* A 2D texture on the same unit: the cube map wins while enabled. */
    glBindTexture(GL_TEXTURE_2D, tex2d);
    glEnable(GL_TEXTURE_2D);
    glMultiTexCoord4f(GL_TEXTURE0, 1, -0.5f, -0.5f, 1);
    full_quad();
    face_texel(0, 1, 1, e);
    CHECK_PIXEL(5, 5, e[0], e[1], e[2], e[3], 0);
    glDisable(GL_TEXTURE_CUBE_MAP_OES);
    full_quad();
    CHECK_PIXEL(5, 5, 255, 255, 255, 255, 0);
    glEnable(GL_TEXTURE_CUBE_MAP_OES);
    glDisable(GL_TEXTURE_2D);
    ct_save("precedence");
}

static void texgen(void)
{
    GLubyte e[4];
    GLint mode = 0;
    static const GLfloat v[12] = {-1, -1, -0.5f, 1, -1, -0.5f, -1, 1, -0.5f, 1, 1, -0.5f};
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v);
    glNormal3f(0, 0, 1);
    glGetTexGenivOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_GEN_MODE_OES, &mode);
    CHECK(mode == GL_REFLECTION_MAP_OES);
    glTexGeniOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_GEN_MODE_OES, GL_REFLECTION_MAP_OES);
    glEnable(GL_TEXTURE_GEN_STR_OES);
    CHECK(glIsEnabled(GL_TEXTURE_GEN_STR_OES));
    /* The eye looks down -z at a quad facing it: reflections point back along +z. */
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    face_texel(4, 0, 1, e);
    CHECK_PIXEL(12, 12, e[0], e[1], e[2], e[3], 0);
    face_texel(4, 1, 0, e);
    CHECK_PIXEL(20, 20, e[0], e[1], e[2], e[3], 0);
    /* NORMAL_MAP: the eye-space normal is the direction. */
    glTexGenfOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_GEN_MODE_OES, (GLfloat)GL_NORMAL_MAP_OES);
    glNormal3f(0.5f, -0.5f, 1);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    face_texel(4, 1, 1, e);
    CHECK_PIXEL(5, 25, e[0], e[1], e[2], e[3], 0);
    glNormal3f(-1, 0.2f, 0.3f);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    face_texel(1, 1, 0, e);
    /* The same direction as the NEGATIVE_X texel (1, 0) of every_face_along_its_axis. */
    {
        GLubyte p[4];
        ct_read(25, 5, p);
        CHECK_MESA_DEVIATES(p[0] == e[0] && p[1] == e[1] && p[2] == e[2],
                            "Mesa 22 llvmpipe samples row 1 here, unlike for the same "
                            "direction given as texture coordinates");
    }
    glDisable(GL_TEXTURE_GEN_STR_OES);
    CHECK_GL(GL_NO_ERROR);
}

static void entry_points_and_errors(GLuint tex2d)
{
    GLint iv = GL_NORMAL_MAP_OES, i = 0;
    GLfloat fv = (GLfloat)GL_REFLECTION_MAP_OES, f = 0;
    GLfixed xv = GL_NORMAL_MAP_OES, x = 0;
    GLuint name = 0;
    GLubyte img[4 * 4 * 4];
    memset(img, 0, sizeof img);
    glTexGenivOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_GEN_MODE_OES, &iv);
    glGetTexGenfvOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_GEN_MODE_OES, &f);
    CHECK(f == (GLfloat)GL_NORMAL_MAP_OES);
    glTexGenfvOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_GEN_MODE_OES, &fv);
    glGetTexGenxvOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_GEN_MODE_OES, &x);
    CHECK(x == GL_REFLECTION_MAP_OES);
    CHECK_GL(GL_NO_ERROR);
    /* Enums pass unconverted through the fixed-point forms (as for glTexParameterx). */
    glTexGenxvOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_GEN_MODE_OES, &xv);
    glGetTexGenivOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_GEN_MODE_OES, &i);
    CHECK_MESA_DEVIATES(i == GL_NORMAL_MAP_OES, "Mesa 22 converts the mode from 16.16");
    glTexGenxOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_GEN_MODE_OES, GL_REFLECTION_MAP_OES);
    glGetTexGenivOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_GEN_MODE_OES, &i);
    CHECK(i == GL_REFLECTION_MAP_OES || !ct_strict());
    CHECK_MESA_DEVIATES(glGetError() == GL_NO_ERROR, "Mesa 22 converts the mode from 16.16");
    glTexGeniOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_GEN_MODE_OES, GL_REFLECTION_MAP_OES);
    CHECK_GL(GL_NO_ERROR);
    /* Bad modes, coordinates and names. */
    glTexGeniOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_GEN_MODE_OES, GL_NEAREST);
    CHECK_GL(GL_INVALID_ENUM);
    glTexGeniOES(GL_TEXTURE_2D, GL_TEXTURE_GEN_MODE_OES, GL_NORMAL_MAP_OES);
    CHECK_GL(GL_INVALID_ENUM);
    glTexGeniOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_MIN_FILTER, GL_NORMAL_MAP_OES);
    CHECK_GL(GL_INVALID_ENUM);
    glGetTexGenivOES(GL_TEXTURE_GEN_STR_OES, GL_TEXTURE_MIN_FILTER, &i);
    CHECK_GL(GL_INVALID_ENUM);
    /* Face images are square. */
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Y_OES, 0, GL_RGBA, 2, 4, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, img);
    CHECK_GL(GL_INVALID_VALUE);
    glCopyTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Y_OES, 0, GL_RGBA, 0, 0, 4, 2, 0);
    CHECK_GL(GL_INVALID_VALUE);
    /* The cube map target itself takes no image. */
    glTexImage2D(GL_TEXTURE_CUBE_MAP_OES, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    CHECK_GL(GL_INVALID_ENUM);
    /* A 2D texture cannot become a cube map, nor the reverse. */
    glBindTexture(GL_TEXTURE_CUBE_MAP_OES, tex2d);
    CHECK_GL(GL_INVALID_OPERATION);
    glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP_OES, (GLint *)&name);
    CHECK(name != tex2d);
    glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP_OES, &i);
    glBindTexture(GL_TEXTURE_2D, (GLuint)i);
    CHECK_GL(GL_INVALID_OPERATION);
    glBindTexture(GL_TEXTURE_2D, 0);
    /* A face of another size leaves the cube map incomplete: the unit is off. */
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Y_OES, 0, GL_RGBA, 4, 4, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, img);
    CHECK_GL(GL_NO_ERROR);
    glColor4f(1, 1, 0, 1);
    glMultiTexCoord4f(GL_TEXTURE0, 1, 0, 0, 1);
    full_quad();
    CHECK_PIXEL(5, 5, 255, 255, 0, 255, 0);
    glColor4f(1, 1, 1, 1);
    ct_save("incomplete");
}

int main(void)
{
    GLuint names[2];
    GLint v = 0;
    GLubyte white[4] = {255, 255, 255, 255};
    ct_init(W, H);
    load();
    CHECK(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_OES_texture_cube_map") != NULL);
    glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE_OES, &v);
    CHECK(v >= 16);
    glGenTextures(2, names);
    glBindTexture(GL_TEXTURE_2D, names[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindTexture(GL_TEXTURE_CUBE_MAP_OES, names[1]);
    glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP_OES, &v);
    CHECK(v == (GLint)names[1]);
    upload_faces();
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    CHECK(!glIsEnabled(GL_TEXTURE_CUBE_MAP_OES));
    glEnable(GL_TEXTURE_CUBE_MAP_OES);
    CHECK(glIsEnabled(GL_TEXTURE_CUBE_MAP_OES));
    CHECK_GL(GL_NO_ERROR);
    every_face_along_its_axis();
    sub_image_copy_and_precedence(names[0]);
    texgen();
    entry_points_and_errors(names[0]);
    glDeleteTextures(2, names);
    return ct_done();
}
