/*
 * OES_fixed_point and OES_single_precision: the extension-suffixed names ES 1.0 programs
 * call (glFrustumfOES, glOrthoxOES, glAlphaFuncxOES, ...) behave as the core functions they
 * name: each call here sets state through the suffixed name and reads it back through a
 * core getter, or compares with the core function's result. Values are exact in 16.16.
 *
 * ct:no-diff (Mesa's libGLESv1_CM exports none of these names, so the program cannot link
 * against it: exactly the programs this extension support is for)
 */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>

#include "common.h"

#define X(v) ((GLfixed)((v) * 65536))

static GLfloat f1(GLenum pname)
{
    GLfloat v[16] = {0};
    glGetFloatv(pname, v);
    return v[0];
}

static int same_matrix(GLenum which, const GLfloat *want)
{
    GLfloat m[16];
    int i;
    glGetFloatv(which, m);
    for (i = 0; i < 16; ++i)
        if (m[i] != want[i])
            return 0;
    return 1;
}

int main(void)
{
    GLfloat m[16], fv[4];
    GLfixed xv[16], mx[16];
    GLint exponent[16];
    int i;
    static const GLfixed plane[4] = {X(1), X(0), X(0), X(2)};
    static const GLfloat planef[4] = {0, 1, 0, 3};
    static const GLfixed color[4] = {X(0.5), X(0.25), X(1), X(1)};

    ct_init(8, 8);
    CHECK(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_OES_fixed_point") != NULL);
    CHECK(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_OES_single_precision") != NULL);

    /* Matrices: each suffixed call against its core twin. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustumf(-1, 1, -1, 1, 1, 3);
    glGetFloatv(GL_PROJECTION_MATRIX, m);
    glLoadIdentity();
    glFrustumfOES(-1, 1, -1, 1, 1, 3);
    CHECK(same_matrix(GL_PROJECTION_MATRIX, m));
    glLoadIdentity();
    glFrustumxOES(X(-1), X(1), X(-1), X(1), X(1), X(3));
    CHECK(same_matrix(GL_PROJECTION_MATRIX, m));
    glLoadIdentity();
    glOrthof(0, 4, 0, 2, -1, 1);
    glGetFloatv(GL_PROJECTION_MATRIX, m);
    glLoadIdentity();
    glOrthofOES(0, 4, 0, 2, -1, 1);
    CHECK(same_matrix(GL_PROJECTION_MATRIX, m));
    glLoadIdentity();
    glOrthoxOES(0, X(4), 0, X(2), X(-1), X(1));
    CHECK(same_matrix(GL_PROJECTION_MATRIX, m));
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(1, 2, 3);
    glScalef(2, 2, 2);
    glRotatef(90, 0, 0, 1);
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    glLoadIdentity();
    glTranslatexOES(X(1), X(2), X(3));
    glScalexOES(X(2), X(2), X(2));
    glRotatexOES(X(90), 0, 0, X(1));
    CHECK(same_matrix(GL_MODELVIEW_MATRIX, m));
    /* A matrix whose entries 16.16 holds exactly. */
    for (i = 0; i < 16; ++i) {
        m[i] = (GLfloat)(i % 5) * 0.25f - 1.0f;
        mx[i] = X(m[i]);
    }
    glLoadMatrixxOES(mx);
    CHECK(same_matrix(GL_MODELVIEW_MATRIX, m));
    glLoadIdentity();
    glMultMatrixxOES(mx);
    CHECK(same_matrix(GL_MODELVIEW_MATRIX, m));
    glLoadIdentity();

    /* Clear values, depth range, current values. */
    glClearColorxOES(X(0.5), X(0.25), 0, X(1));
    glGetFloatv(GL_COLOR_CLEAR_VALUE, fv);
    CHECK(fv[0] == 0.5f && fv[1] == 0.25f && fv[2] == 0 && fv[3] == 1);
    glClearDepthxOES(X(0.5));
    CHECK(f1(GL_DEPTH_CLEAR_VALUE) == 0.5f);
    glClearDepthfOES(0.25f);
    CHECK(f1(GL_DEPTH_CLEAR_VALUE) == 0.25f);
    glDepthRangexOES(X(0.25), X(0.75));
    glGetFloatv(GL_DEPTH_RANGE, fv);
    CHECK(fv[0] == 0.25f && fv[1] == 0.75f);
    glDepthRangefOES(0, 1);
    glGetFloatv(GL_DEPTH_RANGE, fv);
    CHECK(fv[0] == 0 && fv[1] == 1);
    glColor4xOES(X(0.5), X(0.25), 0, X(1));
    glGetFloatv(GL_CURRENT_COLOR, fv);
    CHECK(fv[0] == 0.5f && fv[1] == 0.25f);
    glNormal3xOES(0, X(1), 0);
    glGetFloatv(GL_CURRENT_NORMAL, fv);
    CHECK(fv[0] == 0 && fv[1] == 1 && fv[2] == 0);
    glMultiTexCoord4xOES(GL_TEXTURE0, X(0.5), X(2), 0, X(1));
    glGetFloatv(GL_CURRENT_TEXTURE_COORDS, fv);
    CHECK(fv[0] == 0.5f && fv[1] == 2);

    /* Rasterization and per-fragment state. */
    glLineWidthxOES(X(3));
    CHECK(f1(GL_LINE_WIDTH) == 3);
    glPointSizexOES(X(4));
    CHECK(f1(GL_POINT_SIZE) == 4);
    glPointParameterxOES(GL_POINT_SIZE_MIN, X(2));
    CHECK(f1(GL_POINT_SIZE_MIN) == 2);
    xv[0] = X(1);
    xv[1] = X(0.5);
    xv[2] = 0;
    glPointParameterxvOES(GL_POINT_DISTANCE_ATTENUATION, xv);
    glGetFloatv(GL_POINT_DISTANCE_ATTENUATION, fv);
    CHECK(fv[0] == 1 && fv[1] == 0.5f && fv[2] == 0);
    glPolygonOffsetxOES(X(2), X(3));
    CHECK(f1(GL_POLYGON_OFFSET_FACTOR) == 2 && f1(GL_POLYGON_OFFSET_UNITS) == 3);
    glAlphaFuncxOES(GL_GREATER, X(0.5));
    CHECK(f1(GL_ALPHA_TEST_REF) == 0.5f);
    glSampleCoveragexOES(X(0.5), GL_TRUE);
    CHECK(f1(GL_SAMPLE_COVERAGE_VALUE) == 0.5f);
    glGetFixedvOES(GL_LINE_WIDTH, xv);
    CHECK(xv[0] == X(3));

    /* Clip planes (set under the identity modelview, so read back as given). */
    glClipPlanexOES(GL_CLIP_PLANE0, plane);
    glGetClipPlanexOES(GL_CLIP_PLANE0, xv);
    CHECK(xv[0] == X(1) && xv[1] == 0 && xv[2] == 0 && xv[3] == X(2));
    glClipPlanefOES(GL_CLIP_PLANE1, planef);
    glGetClipPlanefOES(GL_CLIP_PLANE1, fv);
    CHECK(fv[0] == 0 && fv[1] == 1 && fv[2] == 0 && fv[3] == 3);

    /* Fog. */
    glFogxOES(GL_FOG_MODE, GL_LINEAR);
    CHECK(f1(GL_FOG_MODE) == GL_LINEAR);
    glFogxOES(GL_FOG_START, X(2));
    CHECK(f1(GL_FOG_START) == 2);
    glFogxvOES(GL_FOG_COLOR, color);
    glGetFloatv(GL_FOG_COLOR, fv);
    CHECK(fv[0] == 0.5f && fv[1] == 0.25f && fv[2] == 1);

    /* Lighting. */
    glLightxOES(GL_LIGHT0, GL_SPOT_EXPONENT, X(8));
    glGetLightxvOES(GL_LIGHT0, GL_SPOT_EXPONENT, xv);
    CHECK(xv[0] == X(8));
    glLightxvOES(GL_LIGHT1, GL_DIFFUSE, color);
    glGetLightxvOES(GL_LIGHT1, GL_DIFFUSE, xv);
    CHECK(xv[0] == X(0.5) && xv[1] == X(0.25));
    glLightModelxOES(GL_LIGHT_MODEL_TWO_SIDE, X(1));
    CHECK(f1(GL_LIGHT_MODEL_TWO_SIDE) == 1);
    glLightModelxvOES(GL_LIGHT_MODEL_AMBIENT, color);
    glGetFloatv(GL_LIGHT_MODEL_AMBIENT, fv);
    CHECK(fv[0] == 0.5f && fv[1] == 0.25f);
    glMaterialxOES(GL_FRONT_AND_BACK, GL_SHININESS, X(16));
    glGetMaterialxvOES(GL_FRONT, GL_SHININESS, xv);
    CHECK(xv[0] == X(16));
    glMaterialxvOES(GL_FRONT_AND_BACK, GL_EMISSION, color);
    glGetMaterialxvOES(GL_BACK, GL_EMISSION, xv);
    CHECK(xv[0] == X(0.5) && xv[2] == X(1));

    /* Texture environment and parameters. */
    glTexEnvxOES(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glGetTexEnvxvOES(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, xv);
    CHECK(xv[0] == GL_REPLACE);
    glTexEnvxvOES(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, color);
    glGetTexEnvxvOES(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, xv);
    CHECK(xv[0] == X(0.5) && xv[1] == X(0.25));
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexParameterxOES(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glGetTexParameterxvOES(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, xv);
    CHECK(xv[0] == GL_NEAREST);
    xv[0] = GL_CLAMP_TO_EDGE;
    glTexParameterxvOES(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, xv);
    glGetTexParameterxvOES(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, xv);
    CHECK(xv[0] == GL_CLAMP_TO_EDGE);

    /* glQueryMatrixxOES is OES_query_matrix's; here only to see it agrees with the getters. */
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glScalef(2, 2, 2);
    CHECK(glQueryMatrixxOES(xv, exponent) == 0);
    CHECK(ldexp((double)xv[0] / 65536.0, exponent[0]) == 2.0);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
