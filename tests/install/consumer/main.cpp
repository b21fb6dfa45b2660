// Uses the installed headers and library the way an application would.
#include <ivshadow/IvShadowInit.h>
#include <ivshadow/SoDeepShadowLight.h>
#include <ivshadow/SoPeelingSeparator.h>
#include <ivshadow/SoTransparentShadowGroup.h>

#include <cstdio>

int main() {
  ivshadow::init();
  auto* group = new SoTransparentShadowGroup;
  group->ref();
  group->addChild(new SoDeepShadowLight);
  group->addChild(new SoPeelingSeparator);
  std::printf("ivshadow %s: %s with %d children\n", ivshadow::version(),
              group->getTypeId().getName().getString(), group->getNumChildren());
  group->unref();
  return 0;
}
