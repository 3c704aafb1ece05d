"""gacli: equations of motion by the Gibbs-Appell method."""

__version__ = "0.1.0"
