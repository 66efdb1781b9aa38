"""The study evaluations of tools/validation_report.py, one module per paper figure or guide."""
