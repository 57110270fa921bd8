/*
 * Per-fragment state: alpha test, blending, logic op, stencil, sample coverage, polygon
 * offset. Entry points, errors, defaults and query conversions.
 *
 * Checks made only under ct_strict(), where Mesa departs from the specification: Mesa accepts
 * any blend factor on either side and keeps the alpha reference unclamped.
 */
#include "common.h"

#include <math.h>

static GLint geti(GLenum pname)
{
    GLint v = -12345;
    glGetIntegerv(pname, &v);
    return v;
}

static GLfloat getf(GLenum pname)
{
    GLfloat v = -12345.0f;
    glGetFloatv(pname, &v);
    return v;
}

static GLfixed getx(GLenum pname)
{
    GLfixed v = -12345;
    glGetFixedv(pname, &v);
    return v;
}

static GLboolean getb(GLenum pname)
{
    GLboolean v = 77;
    glGetBooleanv(pname, &v);
    return v;
}

int main(void)
{
    ct_init(16, 16);

    /* Defaults (ES 1.1 state tables). */
    CHECK(geti(GL_ALPHA_TEST_FUNC) == GL_ALWAYS);
    CHECK(getf(GL_ALPHA_TEST_REF) == 0.0f);
    CHECK(geti(GL_BLEND_SRC) == GL_ONE);
    CHECK(geti(GL_BLEND_DST) == GL_ZERO);
    CHECK(geti(GL_LOGIC_OP_MODE) == GL_COPY);
    CHECK(geti(GL_STENCIL_FUNC) == GL_ALWAYS);
    CHECK(geti(GL_STENCIL_REF) == 0);
    CHECK((geti(GL_STENCIL_VALUE_MASK) & 0xff) == 0xff);
    CHECK(geti(GL_STENCIL_FAIL) == GL_KEEP);
    CHECK(geti(GL_STENCIL_PASS_DEPTH_FAIL) == GL_KEEP);
    CHECK(geti(GL_STENCIL_PASS_DEPTH_PASS) == GL_KEEP);
    CHECK(getf(GL_SAMPLE_COVERAGE_VALUE) == 1.0f);
    CHECK(getb(GL_SAMPLE_COVERAGE_INVERT) == GL_FALSE);
    CHECK(getf(GL_POLYGON_OFFSET_FACTOR) == 0.0f);
    CHECK(getf(GL_POLYGON_OFFSET_UNITS) == 0.0f);
    CHECK_GL(GL_NO_ERROR);

    /* Alpha test: the reference is clamped to [0, 1]; integer queries map it linearly. */
    glAlphaFunc(GL_GREATER, 0.5f);
    CHECK_GL(GL_NO_ERROR);
    CHECK(geti(GL_ALPHA_TEST_FUNC) == GL_GREATER);
    CHECK(getf(GL_ALPHA_TEST_REF) == 0.5f);
    CHECK(getx(GL_ALPHA_TEST_REF) == 0x8000);
    CHECK(geti(GL_ALPHA_TEST_REF) == 0x3fffffff || geti(GL_ALPHA_TEST_REF) == 0x40000000);
    glAlphaFunc(GL_LESS, 2.0f);
    CHECK_GL(GL_NO_ERROR);
    if (ct_strict()) {
        CHECK(getf(GL_ALPHA_TEST_REF) == 1.0f);
        CHECK(geti(GL_ALPHA_TEST_REF) == 0x7fffffff);
    }
    glAlphaFuncx(GL_EQUAL, -0x10000);
    CHECK_GL(GL_NO_ERROR);
    CHECK(geti(GL_ALPHA_TEST_FUNC) == GL_EQUAL);
    if (ct_strict())
        CHECK(getf(GL_ALPHA_TEST_REF) == 0.0f);
    glAlphaFuncx(GL_NOTEQUAL, 0x4000);
    CHECK(getx(GL_ALPHA_TEST_REF) == 0x4000);
    CHECK(getf(GL_ALPHA_TEST_REF) == 0.25f);
    glAlphaFunc(GL_ONE, 0.75f);
    CHECK_GL(GL_INVALID_ENUM);
    glAlphaFuncx(GL_ZERO, 0);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(geti(GL_ALPHA_TEST_FUNC) == GL_NOTEQUAL);
    CHECK(getf(GL_ALPHA_TEST_REF) == 0.25f);

    /* Blend factors: SRC_COLOR is destination-only, SRC_ALPHA_SATURATE source-only. */
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    CHECK_GL(GL_NO_ERROR);
    CHECK(geti(GL_BLEND_SRC) == GL_SRC_ALPHA);
    CHECK(geti(GL_BLEND_DST) == GL_ONE_MINUS_SRC_ALPHA);
    glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_SRC_COLOR);
    CHECK_GL(GL_NO_ERROR);
    CHECK(geti(GL_BLEND_SRC) == GL_SRC_ALPHA_SATURATE);
    CHECK(geti(GL_BLEND_DST) == GL_SRC_COLOR);
    CHECK(getf(GL_BLEND_DST) == (GLfloat)GL_SRC_COLOR);
    if (ct_strict()) {
        glBlendFunc(GL_SRC_COLOR, GL_ZERO);
        CHECK_GL(GL_INVALID_ENUM);
        glBlendFunc(GL_ONE, GL_SRC_ALPHA_SATURATE);
        CHECK_GL(GL_INVALID_ENUM);
    }
    glBlendFunc(GL_LESS, GL_ONE);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(geti(GL_BLEND_SRC) == GL_SRC_ALPHA_SATURATE);
    CHECK(geti(GL_BLEND_DST) == GL_SRC_COLOR);

    /* Logic op: the sixteen operations. */
    glLogicOp(GL_XOR);
    CHECK_GL(GL_NO_ERROR);
    CHECK(geti(GL_LOGIC_OP_MODE) == GL_XOR);
    glLogicOp(GL_SET);
    CHECK(geti(GL_LOGIC_OP_MODE) == GL_SET);
    glLogicOp(GL_CLEAR);
    CHECK(geti(GL_LOGIC_OP_MODE) == GL_CLEAR);
    glLogicOp(GL_SET + 1);
    CHECK_GL(GL_INVALID_ENUM);
    glLogicOp(GL_ALWAYS);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(geti(GL_LOGIC_OP_MODE) == GL_CLEAR);

    /* Stencil function and operations (8 stencil bits: the reference is clamped to
     * [0, 255] where it is used and queried). */
    glStencilFunc(GL_LEQUAL, 5, 0x0f);
    CHECK_GL(GL_NO_ERROR);
    CHECK(geti(GL_STENCIL_FUNC) == GL_LEQUAL);
    CHECK(geti(GL_STENCIL_REF) == 5);
    CHECK((geti(GL_STENCIL_VALUE_MASK) & 0xff) == 0x0f);
    glStencilFunc(GL_BLEND, 7, 0xff);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(geti(GL_STENCIL_FUNC) == GL_LEQUAL);
    CHECK(geti(GL_STENCIL_REF) == 5);
    glStencilOp(GL_ZERO, GL_INCR, GL_INVERT);
    CHECK_GL(GL_NO_ERROR);
    CHECK(geti(GL_STENCIL_FAIL) == GL_ZERO);
    CHECK(geti(GL_STENCIL_PASS_DEPTH_FAIL) == GL_INCR);
    CHECK(geti(GL_STENCIL_PASS_DEPTH_PASS) == GL_INVERT);
    glStencilOp(GL_REPLACE, GL_DECR, GL_KEEP);
    CHECK(geti(GL_STENCIL_FAIL) == GL_REPLACE);
    CHECK(geti(GL_STENCIL_PASS_DEPTH_FAIL) == GL_DECR);
    CHECK(geti(GL_STENCIL_PASS_DEPTH_PASS) == GL_KEEP);
    glStencilOp(GL_KEEP, GL_KEEP, GL_ONE);
    CHECK_GL(GL_INVALID_ENUM);
    glStencilOp(GL_LESS, GL_KEEP, GL_KEEP);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(geti(GL_STENCIL_FAIL) == GL_REPLACE);
    CHECK(geti(GL_STENCIL_PASS_DEPTH_PASS) == GL_KEEP);

    /* Sample coverage: the value is clamped to [0, 1]. */
    glSampleCoverage(0.25f, GL_TRUE);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_SAMPLE_COVERAGE_VALUE) == 0.25f);
    CHECK(getx(GL_SAMPLE_COVERAGE_VALUE) == 0x4000);
    CHECK(getb(GL_SAMPLE_COVERAGE_INVERT) == GL_TRUE);
    CHECK(geti(GL_SAMPLE_COVERAGE_INVERT) == 1);
    glSampleCoverage(3.0f, GL_FALSE);
    CHECK(getf(GL_SAMPLE_COVERAGE_VALUE) == 1.0f);
    CHECK(getb(GL_SAMPLE_COVERAGE_INVERT) == GL_FALSE);
    glSampleCoveragex(0x8000, GL_TRUE);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_SAMPLE_COVERAGE_VALUE) == 0.5f);
    CHECK(getb(GL_SAMPLE_COVERAGE_INVERT) == GL_TRUE);
    glSampleCoveragex(-0x8000, GL_FALSE);
    CHECK(getf(GL_SAMPLE_COVERAGE_VALUE) == 0.0f);

    /* Polygon offset: any values. */
    glPolygonOffset(1.5f, -2.0f);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_POLYGON_OFFSET_FACTOR) == 1.5f);
    CHECK(getf(GL_POLYGON_OFFSET_UNITS) == -2.0f);
    CHECK(getx(GL_POLYGON_OFFSET_FACTOR) == 0x18000);
    CHECK(geti(GL_POLYGON_OFFSET_UNITS) == -2);
    glPolygonOffsetx(0x28000, 0x10000);
    CHECK_GL(GL_NO_ERROR);
    CHECK(getf(GL_POLYGON_OFFSET_FACTOR) == 2.5f);
    CHECK(getx(GL_POLYGON_OFFSET_UNITS) == 0x10000);

    /* The capabilities that go with this state. */
    glEnable(GL_ALPHA_TEST);
    glEnable(GL_STENCIL_TEST);
    glEnable(GL_COLOR_LOGIC_OP);
    glEnable(GL_SAMPLE_COVERAGE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    CHECK_GL(GL_NO_ERROR);
    CHECK(glIsEnabled(GL_ALPHA_TEST) && getb(GL_ALPHA_TEST));
    CHECK(glIsEnabled(GL_STENCIL_TEST) && getb(GL_STENCIL_TEST));
    CHECK(glIsEnabled(GL_COLOR_LOGIC_OP) && getb(GL_COLOR_LOGIC_OP));
    CHECK(glIsEnabled(GL_SAMPLE_COVERAGE) && getb(GL_SAMPLE_COVERAGE));
    CHECK(glIsEnabled(GL_POLYGON_OFFSET_FILL) && getb(GL_POLYGON_OFFSET_FILL));
    CHECK(!glIsEnabled(GL_BLEND));
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
