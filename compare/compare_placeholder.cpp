// Placeholder until compare/ has sources.
