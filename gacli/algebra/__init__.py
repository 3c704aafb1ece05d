"""algebra: see docs/architecture.md."""
