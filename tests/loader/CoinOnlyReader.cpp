// A stock Coin program that knows nothing of the plugin: it links only Coin. It reads a
// scene file and prints, for each DEF-named node, its type and what it derives from, so the
// test can see that Coin loaded the plugin's nodes from their libraries by name.
// Usage: coin_only_reader FILE.iv
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoPointLight.h>
#include <Inventor/nodes/SoSeparator.h>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: coin_only_reader FILE.iv\n");
    return 2;
  }
  SoDB::init();
  SoInput input;
  if (!input.openFile(argv[1])) return 2;
  SoSeparator* root = SoDB::readAll(&input);
  if (root == nullptr) return 2;
  root->ref();
  SoSearchAction search;
  search.setSearchingAll(TRUE);
  search.setInterest(SoSearchAction::ALL);
  search.setType(SoNode::getClassTypeId());
  search.apply(root);
  for (int i = 0; i < search.getPaths().getLength(); ++i) {
    SoNode* node = search.getPaths()[i]->getTail();
    if (node->getName().getLength() == 0) continue;
    std::printf("%s %s separator=%d pointlight=%d\n", node->getName().getString(),
                node->getTypeId().getName().getString(),
                int(node->isOfType(SoSeparator::getClassTypeId())),
                int(node->isOfType(SoPointLight::getClassTypeId())));
  }
  // The nodes take part in actions like any other.
  SoGetBoundingBoxAction bounds(SbViewportRegion(100, 100));
  bounds.apply(root);
  std::printf("bounds empty=%d\n", int(bounds.getBoundingBox().isEmpty()));
  root->unref();
  return 0;
}
