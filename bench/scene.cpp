#include "scene.h"

namespace bench {

SceneList allScenes(bool quick) {
  SceneList scenes;
  addStackingScenes(scenes, quick);
  addFrictionRampScene(scenes, quick);
  addCircleScenes(scenes, quick);
  addBulletScene(scenes, quick);
  addClosedFormScenes(scenes, quick);
  addSleepingScenes(scenes, quick);
  addJointScenes(scenes, quick);
  return scenes;
}

SceneList box2DSuiteScenes(bool quick) {
  SceneList scenes;
  addBox2DSuiteScenes(scenes, quick);
  return scenes;
}

SceneList solver2DScenes(bool quick) {
  SceneList scenes;
  addSolver2DScenes(scenes, quick);
  return scenes;
}

}  // namespace bench
