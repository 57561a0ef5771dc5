// Reading VRML97 back with Coin3D (Open Inventor with VRML97 nodes), for
// the tests: a real VRML parser, not our own reading.
#pragma once

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/VRMLnodes/SoVRMLAppearance.h>
#include <Inventor/VRMLnodes/SoVRMLImageTexture.h>
#include <Inventor/VRMLnodes/SoVRMLIndexedFaceSet.h>
#include <Inventor/VRMLnodes/SoVRMLShape.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/errors/SoReadError.h>
#include <Inventor/lists/SoPathList.h>
#include <Inventor/nodes/SoSeparator.h>

#include <filesystem>
#include <string>
#include <vector>

namespace pmap::test {

/// Coin's read errors since the last readScene.
inline std::vector<std::string>& coinReadErrors() {
  static std::vector<std::string> errors;
  return errors;
}

inline void collectReadError(const SoError* error, void*) {
  coinReadErrors().push_back(error->getDebugString().getString());
}

/// The scene of `wrl` (referenced; nullptr if Coin cannot read it).
inline SoSeparator* readScene(const std::filesystem::path& wrl) {
  SoDB::init();
  SoReadError::setHandlerCallback(collectReadError, nullptr);
  coinReadErrors().clear();
  SoInput in;
  if (!in.openFile(wrl.c_str())) {
    return nullptr;
  }
  SoSeparator* root = SoDB::readAll(&in);
  if (root != nullptr) {
    root->ref();
  }
  return root;
}

/// The VRML shapes of the scene, in file order.
inline std::vector<SoVRMLShape*> shapesOf(SoNode* root) {
  SoSearchAction search;
  search.setType(SoVRMLShape::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  std::vector<SoVRMLShape*> found;
  const SoPathList& paths = search.getPaths();
  for (int i = 0; i < paths.getLength(); ++i) {
    SoNode* tail = paths[i]->getTail();  // shapes are public children of the root
    if (tail->isOfType(SoVRMLShape::getClassTypeId())) {
      found.push_back(static_cast<SoVRMLShape*>(tail));
    }
  }
  return found;
}

/// `node` as a `Node`, or nullptr when it is of another type.
template <class Node>
Node* as(SoNode* node) {
  return node != nullptr && node->isOfType(Node::getClassTypeId()) ? static_cast<Node*>(node)
                                                                   : nullptr;
}

/// The face sets of the shapes (nullptr for other geometry).
inline std::vector<SoVRMLIndexedFaceSet*> faceSetsOf(const std::vector<SoVRMLShape*>& shapes) {
  std::vector<SoVRMLIndexedFaceSet*> found;
  for (SoVRMLShape* shape : shapes) {
    found.push_back(as<SoVRMLIndexedFaceSet>(shape->geometry.getValue()));
  }
  return found;
}

/// The image textures of the shapes that have one.
inline std::vector<SoVRMLImageTexture*> imageTexturesOf(const std::vector<SoVRMLShape*>& shapes) {
  std::vector<SoVRMLImageTexture*> found;
  for (SoVRMLShape* shape : shapes) {
    auto* appearance = as<SoVRMLAppearance>(shape->appearance.getValue());
    auto* texture = appearance ? as<SoVRMLImageTexture>(appearance->texture.getValue()) : nullptr;
    if (texture != nullptr) {
      found.push_back(texture);
    }
  }
  return found;
}

}  // namespace pmap::test
