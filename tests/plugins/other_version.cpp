// A library marked as a plugin of another ryushi version: refused before it loads.
[[gnu::used]] static const char mark[] = "ryushi-plugin-version=0.0.1;";
