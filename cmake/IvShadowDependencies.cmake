# Every dependency comes from Debian 12 packages; ./run installs them (see README).
find_package(Coin REQUIRED CONFIG)
find_package(SoQt REQUIRED CONFIG)
find_package(Qt5 5.15 REQUIRED COMPONENTS Widgets OpenGL)
find_package(PkgConfig REQUIRED)
pkg_check_modules(EPOXY REQUIRED IMPORTED_TARGET epoxy)
find_package(PNG REQUIRED)
find_package(JPEG REQUIRED)  # libjpeg62-turbo-dev: `-o out.jpg`
find_package(CLI11 REQUIRED CONFIG)
find_package(nlohmann_json 3 REQUIRED CONFIG)
find_package(glm REQUIRED CONFIG)
find_package(embree 3 REQUIRED CONFIG)
