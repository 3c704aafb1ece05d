from fmpy import simulate_fmu

# The plane turns at 2 rad/s; the sphere starts rolling along x at 0.1 m/s.
result = simulate_fmu("sphere.fmu", stop_time=5.0, start_values={"Omega": 2.0, "dot(x)": 0.1})
print(f"x = {result['x'][-1]:.4f}, y = {result['y'][-1]:.4f}")
