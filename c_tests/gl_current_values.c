/*
 * Current normal and texture coordinates, texture unit selection, the normal, texture
 * coordinate and point size arrays, glGetPointerv and the array queries.
 *
 * Checks made only under ct_strict(), where Mesa departs from the specification: Mesa accepts
 * texture units beyond GL_MAX_TEXTURE_UNITS and lets some rejected gl Pointer calls change the
 * array state.
 */
#include "common.h"

static GLint geti(GLenum pname)
{
    GLint v = -12345;
    glGetIntegerv(pname, &v);
    return v;
}

static void *getp(GLenum pname)
{
    void *p = (void *)&p;
    glGetPointerv(pname, &p);
    return p;
}

int main(void)
{
    static const GLfloat data[64];
    static const GLshort shorts[64];
    GLint units = 0;
    GLenum last;
    GLfloat f[4];
    GLfixed x[4];
    GLint iv[4];

    ct_init(16, 16);
    glGetIntegerv(GL_MAX_TEXTURE_UNITS, &units);
    CHECK(units >= 2);
    last = GL_TEXTURE0 + (GLenum)units - 1;
    CHECK_GL(GL_NO_ERROR);

    /* Defaults. */
    glGetFloatv(GL_CURRENT_NORMAL, f);
    CHECK(f[0] == 0 && f[1] == 0 && f[2] == 1);
    glGetFloatv(GL_CURRENT_TEXTURE_COORDS, f);
    CHECK(f[0] == 0 && f[1] == 0 && f[2] == 0 && f[3] == 1);
    CHECK(geti(GL_ACTIVE_TEXTURE) == GL_TEXTURE0);
    CHECK(geti(GL_CLIENT_ACTIVE_TEXTURE) == GL_TEXTURE0);
    CHECK(geti(GL_NORMAL_ARRAY_TYPE) == GL_FLOAT);
    CHECK(geti(GL_NORMAL_ARRAY_STRIDE) == 0);
    CHECK(geti(GL_TEXTURE_COORD_ARRAY_SIZE) == 4);
    CHECK(geti(GL_TEXTURE_COORD_ARRAY_TYPE) == GL_FLOAT);
    CHECK(geti(GL_TEXTURE_COORD_ARRAY_STRIDE) == 0);
    CHECK(geti(GL_POINT_SIZE_ARRAY_TYPE_OES) == GL_FLOAT);
    CHECK(geti(GL_POINT_SIZE_ARRAY_STRIDE_OES) == 0);
    CHECK(geti(GL_VERTEX_ARRAY_SIZE) == 4);
    CHECK(getp(GL_VERTEX_ARRAY_POINTER) == NULL);
    CHECK(getp(GL_NORMAL_ARRAY_POINTER) == NULL);
    CHECK(getp(GL_COLOR_ARRAY_POINTER) == NULL);
    CHECK(getp(GL_TEXTURE_COORD_ARRAY_POINTER) == NULL);
    CHECK(getp(GL_POINT_SIZE_ARRAY_POINTER_OES) == NULL);
    CHECK_GL(GL_NO_ERROR);

    /* Normal: float and fixed; integer queries map [-1, 1] onto the integer range. */
    glNormal3f(0.5f, -1.0f, 2.0f);
    glGetFloatv(GL_CURRENT_NORMAL, f);
    CHECK(f[0] == 0.5f && f[1] == -1.0f && f[2] == 2.0f);
    glGetIntegerv(GL_CURRENT_NORMAL, iv);
    CHECK(iv[1] == -0x7fffffff - 1 || iv[1] == -0x7fffffff);
    glNormal3x(0x10000, 0, -0x8000);
    glGetFixedv(GL_CURRENT_NORMAL, x);
    CHECK(x[0] == 0x10000 && x[1] == 0 && x[2] == -0x8000);
    glGetIntegerv(GL_CURRENT_NORMAL, iv);
    CHECK(iv[0] == 0x7fffffff);
    CHECK_GL(GL_NO_ERROR);

    /* Texture coordinates per unit; the query reads the active unit's. */
    glMultiTexCoord4f(GL_TEXTURE0, 1.0f, 2.0f, 3.0f, 4.0f);
    glMultiTexCoord4x(last, 0x8000, 0x10000, -0x10000, 0x20000);
    CHECK_GL(GL_NO_ERROR);
    glGetFloatv(GL_CURRENT_TEXTURE_COORDS, f);
    CHECK(f[0] == 1.0f && f[1] == 2.0f && f[2] == 3.0f && f[3] == 4.0f);
    glActiveTexture(last);
    CHECK_GL(GL_NO_ERROR);
    CHECK(geti(GL_ACTIVE_TEXTURE) == (GLint)last);
    glGetFloatv(GL_CURRENT_TEXTURE_COORDS, f);
    CHECK(f[0] == 0.5f && f[1] == 1.0f && f[2] == -1.0f && f[3] == 2.0f);
    glGetFixedv(GL_CURRENT_TEXTURE_COORDS, x);
    CHECK(x[0] == 0x8000 && x[3] == 0x20000);
    glGetIntegerv(GL_CURRENT_TEXTURE_COORDS, iv);
    CHECK(iv[1] == 1 && iv[2] == -1 && iv[3] == 2);
    if (ct_strict()) {
        glMultiTexCoord4f(last + 1, 0, 0, 0, 1);
        CHECK_GL(GL_INVALID_ENUM);
        glMultiTexCoord4x(GL_TEXTURE_2D, 0, 0, 0, 0x10000);
        CHECK_GL(GL_INVALID_ENUM);
        glGetFloatv(GL_CURRENT_TEXTURE_COORDS, f);
        CHECK(f[0] == 0.5f && f[3] == 2.0f);
    }

    /* Active texture: INVALID_ENUM outside TEXTURE0 .. TEXTURE0 + units - 1. */
    if (ct_strict()) {
        glActiveTexture(last + 1);
        CHECK_GL(GL_INVALID_ENUM);
    }
    glActiveTexture(GL_TEXTURE0 - 1);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(geti(GL_ACTIVE_TEXTURE) == (GLint)last);
    glActiveTexture(GL_TEXTURE0);
    CHECK(geti(GL_ACTIVE_TEXTURE) == GL_TEXTURE0);

    /* Client active texture selects the texture coordinate array. */
    glClientActiveTexture(last);
    CHECK_GL(GL_NO_ERROR);
    CHECK(geti(GL_CLIENT_ACTIVE_TEXTURE) == (GLint)last);
    glClientActiveTexture(last + 1);
    CHECK_GL(GL_INVALID_ENUM);
    glClientActiveTexture(GL_TEXTURE_2D);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(geti(GL_CLIENT_ACTIVE_TEXTURE) == (GLint)last);

    glTexCoordPointer(2, GL_SHORT, 8, shorts);
    CHECK_GL(GL_NO_ERROR);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    CHECK(geti(GL_TEXTURE_COORD_ARRAY_SIZE) == 2);
    CHECK(geti(GL_TEXTURE_COORD_ARRAY_TYPE) == GL_SHORT);
    CHECK(geti(GL_TEXTURE_COORD_ARRAY_STRIDE) == 8);
    CHECK(getp(GL_TEXTURE_COORD_ARRAY_POINTER) == (void *)shorts);
    CHECK(glIsEnabled(GL_TEXTURE_COORD_ARRAY));
    glClientActiveTexture(GL_TEXTURE0);
    CHECK(geti(GL_TEXTURE_COORD_ARRAY_SIZE) == 4);
    CHECK(getp(GL_TEXTURE_COORD_ARRAY_POINTER) == NULL);
    CHECK(!glIsEnabled(GL_TEXTURE_COORD_ARRAY));
    glTexCoordPointer(3, GL_BYTE, 0, data);
    glTexCoordPointer(4, GL_FIXED, 16, data);
    glTexCoordPointer(3, GL_FLOAT, 12, data);
    CHECK_GL(GL_NO_ERROR);
    CHECK(geti(GL_TEXTURE_COORD_ARRAY_SIZE) == 3);
    CHECK(geti(GL_TEXTURE_COORD_ARRAY_TYPE) == GL_FLOAT);
    CHECK(geti(GL_TEXTURE_COORD_ARRAY_STRIDE) == 12);
    glTexCoordPointer(1, GL_FLOAT, 0, shorts);
    CHECK_GL(GL_INVALID_VALUE);
    glTexCoordPointer(5, GL_FLOAT, 0, shorts);
    CHECK_GL(GL_INVALID_VALUE);
    glTexCoordPointer(2, GL_FLOAT, -4, shorts);
    CHECK_GL(GL_INVALID_VALUE);
    glTexCoordPointer(2, GL_UNSIGNED_BYTE, 0, shorts);
    CHECK_GL(GL_INVALID_ENUM);
    glTexCoordPointer(2, GL_UNSIGNED_SHORT, 0, shorts);
    CHECK_GL(GL_INVALID_ENUM);
    if (ct_strict()) {
        CHECK(geti(GL_TEXTURE_COORD_ARRAY_SIZE) == 3);
        CHECK(getp(GL_TEXTURE_COORD_ARRAY_POINTER) == (void *)data);
    }

    /* Normal array: BYTE, SHORT, FIXED, FLOAT. */
    glNormalPointer(GL_BYTE, 3, data);
    glNormalPointer(GL_SHORT, 6, shorts);
    CHECK_GL(GL_NO_ERROR);
    CHECK(geti(GL_NORMAL_ARRAY_TYPE) == GL_SHORT);
    CHECK(geti(GL_NORMAL_ARRAY_STRIDE) == 6);
    CHECK(getp(GL_NORMAL_ARRAY_POINTER) == (void *)shorts);
    glNormalPointer(GL_FIXED, 0, data);
    glNormalPointer(GL_FLOAT, 16, data);
    CHECK_GL(GL_NO_ERROR);
    glNormalPointer(GL_UNSIGNED_BYTE, 0, shorts);
    CHECK_GL(GL_INVALID_ENUM);
    glNormalPointer(GL_UNSIGNED_SHORT, 0, shorts);
    CHECK_GL(GL_INVALID_ENUM);
    glNormalPointer(GL_FLOAT, -1, shorts);
    CHECK_GL(GL_INVALID_VALUE);
    if (ct_strict()) {
        CHECK(geti(GL_NORMAL_ARRAY_TYPE) == GL_FLOAT);
        CHECK(geti(GL_NORMAL_ARRAY_STRIDE) == 16);
        CHECK(getp(GL_NORMAL_ARRAY_POINTER) == (void *)data);
    }
    glEnableClientState(GL_NORMAL_ARRAY);
    CHECK(glIsEnabled(GL_NORMAL_ARRAY));

    /* Point size array (OES_point_size_array): FIXED or FLOAT. */
    glPointSizePointerOES(GL_FIXED, 4, data);
    CHECK_GL(GL_NO_ERROR);
    CHECK(geti(GL_POINT_SIZE_ARRAY_TYPE_OES) == GL_FIXED);
    CHECK(geti(GL_POINT_SIZE_ARRAY_STRIDE_OES) == 4);
    CHECK(getp(GL_POINT_SIZE_ARRAY_POINTER_OES) == (void *)data);
    glPointSizePointerOES(GL_SHORT, 0, shorts);
    CHECK_GL(GL_INVALID_ENUM);
    glPointSizePointerOES(GL_BYTE, 0, shorts);
    CHECK_GL(GL_INVALID_ENUM);
    glPointSizePointerOES(GL_FLOAT, -4, shorts);
    CHECK_GL(GL_INVALID_VALUE);
    if (ct_strict())
        CHECK(geti(GL_POINT_SIZE_ARRAY_TYPE_OES) == GL_FIXED);
    glPointSizePointerOES(GL_FLOAT, 0, shorts);
    CHECK(geti(GL_POINT_SIZE_ARRAY_TYPE_OES) == GL_FLOAT);
    CHECK(getp(GL_POINT_SIZE_ARRAY_POINTER_OES) == (void *)shorts);
    glEnableClientState(GL_POINT_SIZE_ARRAY_OES);
    CHECK(glIsEnabled(GL_POINT_SIZE_ARRAY_OES));
    CHECK_GL(GL_NO_ERROR);

    /* Vertex and color pointers through glGetPointerv. */
    glVertexPointer(3, GL_FLOAT, 0, data);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, shorts);
    CHECK(getp(GL_VERTEX_ARRAY_POINTER) == (void *)data);
    CHECK(getp(GL_COLOR_ARRAY_POINTER) == (void *)shorts);
    CHECK_GL(GL_NO_ERROR);
    {
        void *p = (void *)&p;
        glGetPointerv(GL_VERTEX_ARRAY, &p);
        CHECK_GL(GL_INVALID_ENUM);
        glGetPointerv(GL_TEXTURE_2D, &p);
        CHECK_GL(GL_INVALID_ENUM);
    }
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_POINT_SIZE_ARRAY_OES);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
