"""The C wrapper of an FMU: the FMI 2.0 Model Exchange functions over the generated ``NAME_rhs``.

The wrapper holds no equation: ``fmi2GetDerivatives`` calls the rhs of the
generated C (:mod:`gacli.emit.c`), so the FMU and ``--format c`` are one
code path. Every real of the model lives in one array indexed by value
reference (x, then der(x), then p, then r: :func:`gacli.emit.fmu_xml.variables`).

The FMI 2.0 types and function declarations are written here from the
standard's ABI, not copied from the Modelica Association's headers; they
sit inside ``#ifndef fmi2Functions_h``, so that a tool compiling the
sources with the official ``fmi2Functions.h`` included first gets its
declarations checked against ours (tests/test_emit_fmu.py does that with
the headers FMPy ships). ``FMI2_FUNCTION_PREFIX`` renames the functions as
the standard asks for source FMUs linked statically.
"""

from __future__ import annotations

from string import Template

from gacli.emit.c import comment_text
from gacli.emit.fmu_calls import MODEL_EXCHANGE, STATE, UNSUPPORTED

# Only the start of the file is a Template: the functions below have no placeholder but
# NAME_rhs and PREFIX_N..., replaced as plain text, so that C reads as written.
PROLOGUE = Template('''\
$comment
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "$name.h"

#ifndef fmi2Functions_h
/* FMI 2.0 platform types and callbacks (fmi2TypesPlatform.h, fmi2FunctionTypes.h). */
typedef void *fmi2Component;
typedef void *fmi2ComponentEnvironment;
typedef void *fmi2FMUstate;
typedef unsigned int fmi2ValueReference;
typedef double fmi2Real;
typedef int fmi2Integer;
typedef int fmi2Boolean;
typedef char fmi2Char;
typedef const fmi2Char *fmi2String;
typedef char fmi2Byte;
#define fmi2True 1
#define fmi2False 0
typedef enum { fmi2OK, fmi2Warning, fmi2Discard, fmi2Error, fmi2Fatal, fmi2Pending } fmi2Status;
typedef enum { fmi2ModelExchange, fmi2CoSimulation } fmi2Type;
typedef void (*fmi2CallbackLogger)(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String, fmi2String, ...);
typedef void *(*fmi2CallbackAllocateMemory)(size_t, size_t);
typedef void (*fmi2CallbackFreeMemory)(void *);
typedef void (*fmi2StepFinished)(fmi2ComponentEnvironment, fmi2Status);
typedef struct {
    const fmi2CallbackLogger logger;
    const fmi2CallbackAllocateMemory allocateMemory;
    const fmi2CallbackFreeMemory freeMemory;
    const fmi2StepFinished stepFinished;
    const fmi2ComponentEnvironment componentEnvironment;
} fmi2CallbackFunctions;
typedef struct {
    fmi2Boolean newDiscreteStatesNeeded;
    fmi2Boolean terminateSimulation;
    fmi2Boolean nominalsOfContinuousStatesChanged;
    fmi2Boolean valuesOfContinuousStatesChanged;
    fmi2Boolean nextEventTimeDefined;
    fmi2Real nextEventTime;
} fmi2EventInfo;
#define fmi2TypesPlatform "default"
#define fmi2Version "2.0"
#if defined(_WIN32)
#define FMI2_Export __declspec(dllexport)
#elif defined(__GNUC__)
#define FMI2_Export __attribute__((visibility("default")))
#else
#define FMI2_Export
#endif
/* A source FMU linked statically gets its functions renamed PREFIXfmi2...: */
#ifdef FMI2_FUNCTION_PREFIX
#define fmi2Paste(a, b) a ## b
#define fmi2PasteB(a, b) fmi2Paste(a, b)
#define fmi2FullName(name) fmi2PasteB(FMI2_FUNCTION_PREFIX, name)
$renames
#endif
#endif

#define GUID "$guid"
/* Value references: the state x, its derivative, the parameters p, the arguments r. */
#define VR_X 0
#define VR_DX (VR_X + ${prefix}_NX)
#define VR_P (VR_DX + ${prefix}_NX)
#define VR_R (VR_P + ${prefix}_NP)
#define NV (VR_R + ${prefix}_NR)

/* The parameters' start values, in the order of p (0 where the file gives none). */
static const double DEFAULTS[${prefix}_NP + 1] = {$defaults};
''')

FUNCTIONS = ("GetTypesPlatform GetVersion SetDebugLogging Instantiate FreeInstance SetupExperiment "
             "EnterInitializationMode ExitInitializationMode Terminate Reset GetReal GetInteger GetBoolean "
             "GetString SetReal SetInteger SetBoolean SetString GetFMUstate SetFMUstate FreeFMUstate "
             "SerializedFMUstateSize SerializeFMUstate DeSerializeFMUstate GetDirectionalDerivative "
             "EnterEventMode NewDiscreteStates EnterContinuousTimeMode CompletedIntegratorStep SetTime "
             "SetContinuousStates GetDerivatives GetEventIndicators GetContinuousStates "
             "GetNominalsOfContinuousStates").split()

BODY = r'''
typedef enum { INSTANTIATED, INITIALIZATION, RUNNING, TERMINATED } Mode;

typedef struct {
    fmi2CallbackLogger logger;
    fmi2CallbackFreeMemory freeMemory;
    fmi2ComponentEnvironment environment;
    char *instanceName;
    int loggingOn;
    Mode mode;
    double time;
    double v[NV];
} Instance;

static void note(Instance *m, fmi2Status status, const char *category, const char *format, ...)
{
    char message[512];
    va_list args;
    if (m->logger == NULL || (status == fmi2OK && !m->loggingOn)) {
        return;
    }
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    m->logger(m->environment, m->instanceName, status, category, "%s", message);
}

static fmi2Status fail(fmi2Component c, const char *function, const char *why)
{
    if (c == NULL) {
        return fmi2Error;
    }
    note((Instance *)c, fmi2Error, "logStatusError", "%s: %s", function, why);
    return fmi2Error;
}

static void start_values(Instance *m)
{
    int i;
    m->time = 0.0;
    for (i = 0; i < NV; ++i) {
        m->v[i] = 0.0;
    }
    for (i = 0; i < PREFIX_NP; ++i) {
        m->v[VR_P + i] = DEFAULTS[i];
    }
}

/* der(x) at the current time and values: the generated rhs, with M u' = F solved by Cholesky. */
static fmi2Status derivatives(Instance *m)
{
    int pivot = NAME_rhs(m->time, m->v + VR_X, m->v + VR_P, m->v + VR_R, m->v + VR_DX);
    if (pivot < 0) {
        note(m, fmi2Error, "logStatusError",
             "the equations are undefined at t = %g: a value is not finite (a function outside its domain, "
             "a division by zero or an overflow): check the parameters, the inputs and the state", m->time);
        return fmi2Error;
    }
    if (pivot != 0) {
        note(m, fmi2Error, "logStatusError",
             "the mass matrix is not positive definite at t = %g (pivot %d): check the parameters and the state",
             m->time, pivot);
        return fmi2Error;
    }
    return fmi2OK;
}

FMI2_Export const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }

FMI2_Export const char *fmi2GetVersion(void) { return fmi2Version; }

FMI2_Export fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                                           const fmi2String categories[])
{
    (void)nCategories;
    (void)categories;
    ((Instance *)c)->loggingOn = loggingOn;
    return fmi2OK;
}

FMI2_Export fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                                          fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                                          fmi2Boolean visible, fmi2Boolean loggingOn)
{
    Instance *m;
    const char *name = instanceName != NULL ? instanceName : "";
    (void)fmuResourceLocation;
    (void)visible;
    if (functions == NULL || fmuType != fmi2ModelExchange || fmuGUID == NULL || strcmp(fmuGUID, GUID) != 0) {
        if (functions != NULL && functions->logger != NULL) {
            functions->logger(functions->componentEnvironment, name, fmi2Error, "logStatusError",
                              "fmi2Instantiate: this FMU is Model Exchange only, with guid %s", GUID);
        }
        return NULL;
    }
    m = functions->allocateMemory != NULL ? (Instance *)functions->allocateMemory(1, sizeof(Instance))
                                          : (Instance *)calloc(1, sizeof(Instance));
    if (m == NULL) {
        return NULL;
    }
    m->instanceName = functions->allocateMemory != NULL ? (char *)functions->allocateMemory(strlen(name) + 1, 1)
                                                        : (char *)calloc(strlen(name) + 1, 1);
    if (m->instanceName != NULL) {
        strcpy(m->instanceName, name);
    }
    m->logger = functions->logger;
    m->freeMemory = functions->allocateMemory != NULL ? functions->freeMemory : free;
    m->environment = functions->componentEnvironment;
    m->loggingOn = loggingOn;
    m->mode = INSTANTIATED;
    start_values(m);
    return m;
}

FMI2_Export void fmi2FreeInstance(fmi2Component c)
{
    Instance *m = (Instance *)c;
    if (m == NULL) {
        return;
    }
    if (m->freeMemory != NULL) {
        m->freeMemory(m->instanceName);
        m->freeMemory(m);
    }
}

FMI2_Export fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                                           fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    (void)toleranceDefined;
    (void)tolerance;
    (void)stopTimeDefined;
    (void)stopTime;
    ((Instance *)c)->time = startTime;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
    ((Instance *)c)->mode = INITIALIZATION;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    ((Instance *)c)->mode = RUNNING;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2Terminate(fmi2Component c)
{
    ((Instance *)c)->mode = TERMINATED;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2Reset(fmi2Component c)
{
    Instance *m = (Instance *)c;
    m->mode = INSTANTIATED;
    start_values(m);
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[])
{
    Instance *m = (Instance *)c;
    size_t i;
    int fresh = 0;
    for (i = 0; i < nvr; ++i) {
        if (vr[i] >= NV) {
            return fail(c, "fmi2GetReal", "no variable has this value reference");
        }
        if (vr[i] >= VR_DX && vr[i] < VR_P && !fresh) {
            if (derivatives(m) != fmi2OK) {
                return fmi2Error;
            }
            fresh = 1;
        }
        value[i] = m->v[vr[i]];
    }
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                   const fmi2Real value[])
{
    Instance *m = (Instance *)c;
    size_t i;
    for (i = 0; i < nvr; ++i) {
        if (vr[i] >= NV || (vr[i] >= VR_DX && vr[i] < VR_P)) {
            return fail(c, "fmi2SetReal", "only states, parameters and inputs can be set");
        }
        if (vr[i] >= VR_P && vr[i] < VR_R && m->mode != INSTANTIATED && m->mode != INITIALIZATION) {
            return fail(c, "fmi2SetReal", "the parameters are fixed once initialization is over");
        }
    }
    for (i = 0; i < nvr; ++i) {
        m->v[vr[i]] = value[i];
    }
    return fmi2OK;
}
'''

KINDS = (("Integer", "fmi2Integer"), ("Boolean", "fmi2Boolean"), ("String", "fmi2String"))


def wrapper(*, name: str, prefix: str, guid: str, defaults: list[float], comment_lines: list[str]) -> str:
    """The text of ``NAME_fmu.c`` for the system ``name`` (upper case ``prefix``)."""
    comment = "\n".join(["/* " + comment_text(comment_lines[0]),
                         *(" * " + comment_text(line) for line in comment_lines[1:]), " */"])
    renames = "\n".join(f"#define fmi2{f} fmi2FullName(fmi2{f})" for f in FUNCTIONS)
    # One extra slot: C99 has no empty array, and a system may have no parameter.
    values = ", ".join(repr(float(v)) for v in [*defaults, 0.0])
    prologue = PROLOGUE.substitute(comment=comment, name=name, prefix=prefix, guid=guid, renames=renames,
                                   defaults=values)
    unsupported = "".join(UNSUPPORTED.format(kind=kind, type=type_) for kind, type_ in KINDS)
    functions = BODY + unsupported + STATE + MODEL_EXCHANGE
    return prologue + functions.replace("PREFIX_N", f"{prefix}_N").replace("NAME_rhs", f"{name}_rhs")
