"""The FMI 2.0 calls of the FMU wrapper that have little to do (see :mod:`gacli.emit.fmu_c`).

The system is smooth and its only variables are reals: no events, no
integer, boolean or string variables, no FMU state and no directional
derivatives (modelDescription.xml says so), so these calls either accept
and do nothing, or fail with a message through the logger.
"""

# Integer, Boolean and String variables there are none, and no FMU state or directional
# derivative is offered (modelDescription says so): a call with values to get or set fails.
UNSUPPORTED = r'''
FMI2_Export fmi2Status fmi2Get{kind}(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, {type} value[])
{{
    (void)vr;
    (void)value;
    return nvr == 0 ? fmi2OK : fail(c, "fmi2Get{kind}", "this FMU has only Real variables");
}}

FMI2_Export fmi2Status fmi2Set{kind}(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                     const {type} value[])
{{
    (void)vr;
    (void)value;
    return nvr == 0 ? fmi2OK : fail(c, "fmi2Set{kind}", "this FMU has only Real variables");
}}
'''

STATE = r'''
FMI2_Export fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate)
{
    (void)FMUstate;
    return fail(c, "fmi2GetFMUstate", "not supported (canGetAndSetFMUstate is false)");
}

FMI2_Export fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate)
{
    (void)FMUstate;
    return fail(c, "fmi2SetFMUstate", "not supported (canGetAndSetFMUstate is false)");
}

FMI2_Export fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate)
{
    (void)FMUstate;
    return fail(c, "fmi2FreeFMUstate", "not supported (canGetAndSetFMUstate is false)");
}

FMI2_Export fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t *size)
{
    (void)FMUstate;
    (void)size;
    return fail(c, "fmi2SerializedFMUstateSize", "not supported (canSerializeFMUstate is false)");
}

FMI2_Export fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[],
                                             size_t size)
{
    (void)FMUstate;
    (void)serializedState;
    (void)size;
    return fail(c, "fmi2SerializeFMUstate", "not supported (canSerializeFMUstate is false)");
}

FMI2_Export fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                               fmi2FMUstate *FMUstate)
{
    (void)serializedState;
    (void)size;
    (void)FMUstate;
    return fail(c, "fmi2DeSerializeFMUstate", "not supported (canSerializeFMUstate is false)");
}

FMI2_Export fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[],
                                                    size_t nUnknown, const fmi2ValueReference vKnown_ref[],
                                                    size_t nKnown, const fmi2Real dvKnown[], fmi2Real dvUnknown[])
{
    (void)vUnknown_ref;
    (void)nUnknown;
    (void)vKnown_ref;
    (void)nKnown;
    (void)dvKnown;
    (void)dvUnknown;
    return fail(c, "fmi2GetDirectionalDerivative", "not supported (providesDirectionalDerivative is false)");
}
'''

# No event indicators and no time events: the system is smooth, event mode has nothing to do.
MODEL_EXCHANGE = r'''
FMI2_Export fmi2Status fmi2EnterEventMode(fmi2Component c)
{
    (void)c;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *eventInfo)
{
    (void)c;
    eventInfo->newDiscreteStatesNeeded = fmi2False;
    eventInfo->terminateSimulation = fmi2False;
    eventInfo->nominalsOfContinuousStatesChanged = fmi2False;
    eventInfo->valuesOfContinuousStatesChanged = fmi2False;
    eventInfo->nextEventTimeDefined = fmi2False;
    eventInfo->nextEventTime = 0.0;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c)
{
    (void)c;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean noSetFMUStatePriorToCurrentPoint,
                                                   fmi2Boolean *enterEventMode, fmi2Boolean *terminateSimulation)
{
    (void)c;
    (void)noSetFMUStatePriorToCurrentPoint;
    *enterEventMode = fmi2False;
    *terminateSimulation = fmi2False;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time)
{
    ((Instance *)c)->time = time;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t nx)
{
    size_t i;
    if (nx != PREFIX_NX) {
        return fail(c, "fmi2SetContinuousStates", "nx is not the number of states");
    }
    for (i = 0; i < nx; ++i) {
        ((Instance *)c)->v[VR_X + i] = x[i];
    }
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real derivatives_[], size_t nx)
{
    Instance *m = (Instance *)c;
    size_t i;
    if (nx != PREFIX_NX) {
        return fail(c, "fmi2GetDerivatives", "nx is not the number of states");
    }
    if (derivatives(m) != fmi2OK) {
        return fmi2Error;
    }
    for (i = 0; i < nx; ++i) {
        derivatives_[i] = m->v[VR_DX + i];
    }
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real eventIndicators[], size_t ni)
{
    (void)eventIndicators;
    return ni == 0 ? fmi2OK : fail(c, "fmi2GetEventIndicators", "this FMU has no event indicators");
}

FMI2_Export fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx)
{
    size_t i;
    if (nx != PREFIX_NX) {
        return fail(c, "fmi2GetContinuousStates", "nx is not the number of states");
    }
    for (i = 0; i < nx; ++i) {
        x[i] = ((Instance *)c)->v[VR_X + i];
    }
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x_nominal[], size_t nx)
{
    size_t i;
    (void)c;
    for (i = 0; i < nx; ++i) {
        x_nominal[i] = 1.0;
    }
    return fmi2OK;
}
'''
