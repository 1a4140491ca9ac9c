import { AccessTokensPage } from "@/features/account/access-tokens-page";

export default function Page() {
  return <AccessTokensPage />;
}
