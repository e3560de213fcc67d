// Placeholder until povgen/ has sources.
