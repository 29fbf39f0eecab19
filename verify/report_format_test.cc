// Placeholder filled in below.
