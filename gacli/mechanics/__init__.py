"""mechanics: see docs/architecture.md."""
