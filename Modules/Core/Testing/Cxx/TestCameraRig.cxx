int TestCameraRig(int, char*[]) { return 0; }
