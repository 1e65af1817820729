// Keeps test_support non-empty until its sources exist.
